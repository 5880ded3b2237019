using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>Regions in code no build compiles (<c>#if false</c>) are not binding points, Debug-only or Release-only ones are; region diagnostics sit at the region's column.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_InactiveRegions : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string Text = """
        namespace Sample;

        public static class Cross
        {
            public static void Run(V u, V v, V w)
            {
        #if false
                #region GMac : NoSuchMacro
                //GMac.Bind("u", "Vector3D", u);
                kept as it is
                #endregion
        #endif
                #region GMac : NormalToVectors
                //GMac.Bind("u", "Vector3D", u);
                //GMac.Bind("v", "Vector3D", v);
                //GMac.Bind("w", "Vector3D", w);
                #endregion
            }
        }
        """;

    [Fact]
    public void Region_under_if_false_is_left_alone()
    {
        var path = _temp.Write("Cross.cs", Text);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.True(exit == 0, err);
        var text = File.ReadAllText(path);
        Assert.Contains("        kept as it is\n", text);
        Assert.Contains("w.x = ", text);
    }

    [Theory]
    [InlineData("#if DEBUG")]
    [InlineData("#if !DEBUG")]
    [InlineData("#if TRACE && DEBUG")]
    public void Region_compiled_in_debug_or_release_builds_is_generated(string condition)
    {
        var text = $$"""
            namespace Sample;

            public static class Cross
            {
                public static void Run(V u, V v, V w)
                {
            {{condition}}
                    #region GMac : NormalToVectors
                    //GMac.Bind("u", "Vector3D", u);
                    //GMac.Bind("v", "Vector3D", v);
                    //GMac.Bind("w", "Vector3D", w);
                    #endregion
            #endif
                }
            }
            """;
        var path = _temp.Write("Cross.cs", text);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.True(exit == 0, err);
        Assert.Contains("w.x = ", File.ReadAllText(path));
    }

    [Fact]
    public void Region_errors_are_reported_at_the_region_column()
    {
        var path = _temp.Write("Cross.cs", Text.Replace("#if false\n", "").Replace("#endif\n", ""));

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Contains("Cross.cs(7,9): error GMAC0301: unknown macro 'NoSuchMacro'", err);
    }
}
