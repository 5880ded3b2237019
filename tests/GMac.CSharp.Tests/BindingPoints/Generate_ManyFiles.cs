using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// Files are generated on several threads at once: each file must come out as it does when it is
/// generated alone, and diagnostics must be reported in the order of the files.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_ManyFiles : IDisposable
{
    private readonly TempFolder _together = new();
    private readonly TempFolder _alone = new();

    public void Dispose()
    {
        _together.Dispose();
        _alone.Dispose();
    }

    /// <summary>Three macros over 3D vectors, each with its bind lines.</summary>
    private static readonly (string Macro, string Binds)[] Regions =
    [
        ("NormalToVectors", """
                    //GMac.Bind("u", "Vector3D", "a");
                    //GMac.Bind("v", "Vector3D", "b");
                    //GMac.Bind("w", "Vector3D", "r");
        """),
        ("GramSchmidtRejection", """
                    //GMac.Bind("v1", "Vector3D", "a");
                    //GMac.Bind("v2", "Vector3D", "b");
                    //GMac.Bind("v3", "Vector3D", "c");
                    //GMac.Bind("w1", "Vector3D", "r");
                    //GMac.Bind("w2", "Vector3D", "s");
                    //GMac.Bind("w3", "Vector3D", "t");
        """),
        ("SkewLinesClosestPoints", """
                    //GMac.Bind("p1", "Vector3D", "a");
                    //GMac.Bind("d1", "Vector3D", "b");
                    //GMac.Bind("p2", "Vector3D", "c");
                    //GMac.Bind("d2", "Vector3D", "d");
                    //GMac.Bind("t1.1", "<x>");
                    //GMac.Bind("t2.1", "<y>");
        """),
    ];

    /// <summary>A file with one region (its #region at line 7); when <paramref name="broken"/>, of a macro that does not exist.</summary>
    private static string FileWith(int index, bool broken)
    {
        var (macro, binds) = Regions[index % Regions.Length];
        return $$"""
            namespace Sample;

            public static class Kernel{{index}}
            {
                public static void Run(V a, V b, V c, V d, V r, V s, V t, ref double x, ref double y)
                {
                    #region GMac : {{(broken ? "NoSuchMacro" : macro)}}
            {{binds}}
                    #endregion
                }
            }
            """;
    }

    [Fact]
    public void Every_file_comes_out_as_when_generated_alone_and_errors_keep_the_file_order()
    {
        var names = new List<string>();
        for (var i = 0; i < 18; i++)
        {
            var name = $"K{i:00}.cs";
            var text = FileWith(i, broken: i % 7 == 3);
            _together.Write(name, text);
            _alone.Write(name, text);
            names.Add(name);
        }

        var (exit, _, err) = Tool.Generate([_together.Path]);

        Assert.Equal(1, exit);
        var reported = err.Split('\n').Where(l => l.Contains("error GMAC")).Select(l => Path.GetFileName(l[..l.IndexOf('(')])).ToList();
        Assert.True(reported.SequenceEqual(["K03.cs", "K10.cs", "K17.cs"]), err);
        foreach (var name in names)
        {
            var alonePath = Path.Combine(_alone.Path, name);
            Tool.Generate([alonePath]);
            Assert.Equal(File.ReadAllText(alonePath), File.ReadAllText(Path.Combine(_together.Path, name)));
        }
        Assert.Contains("GramSchmidtRejection", File.ReadAllText(Path.Combine(_together.Path, "K01.cs")));
        Assert.Contains("double ", File.ReadAllText(Path.Combine(_together.Path, "K01.cs")));
    }
}
