using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>With a cache folder, files left up to date are skipped next time, and any edit brings them back.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_FileIndex : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [Fact]
    public void Unchanged_files_are_skipped_and_edited_ones_regenerated()
    {
        var context = new GenerationContext(SharedDsl.Context.Project, Path.Combine(_temp.Path, ".gmac-cache"));
        var code = Path.Combine(_temp.Path, "code");
        Directory.CreateDirectory(code);
        var path = Path.Combine(code, "TriangleNormal.cs");
        File.Copy(Path.Combine(SharedDsl.RepositoryRoot, "src/RayTracer/Kernels/TriangleNormal.cs"), path);
        Assert.Equal(0, Tool.Generate([code], context: context).Exit);
        var generated = File.ReadAllText(path);

        var (_, second, _) = Tool.Generate([code], context: context);
        Assert.Contains("1 file(s) unchanged since the last run", second);

        // A hand edit inside the region makes the file differ from what the index recorded.
        File.WriteAllText(path, generated.Replace("n.x = ", "n.x = 2 * "));
        var (exit, third, _) = Tool.Generate([code], context: context);
        Assert.Equal(0, exit);
        Assert.Contains("1 file(s) changed", third);
        Assert.Equal(generated, File.ReadAllText(path));
    }
}
