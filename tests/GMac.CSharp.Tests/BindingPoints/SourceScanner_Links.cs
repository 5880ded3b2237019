using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>The scanner lists each C# file once, whatever links lead to it, and never reads special files.</summary>
public sealed class SourceScanner_Links : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [Fact]
    public void A_link_to_an_ancestor_folder_lists_each_file_once()
    {
        var a = _temp.Write("code/A.cs", "class A { }");
        var b = _temp.Write("code/sub/B.cs", "class B { }");
        Directory.CreateSymbolicLink(Path.Combine(_temp.Path, "code/sub/loop"), "..");

        var scan = SourceScanner.Scan([Path.Combine(_temp.Path, "code")]);

        Assert.Equal([a, b], scan.Files);
        Assert.Empty(scan.Problems);
    }

    [Fact]
    public void A_file_and_a_link_to_it_are_one_file()
    {
        var a = _temp.Write("code/A.cs", "class A { }");
        File.CreateSymbolicLink(Path.Combine(_temp.Path, "code/Z.cs"), "A.cs");

        var scan = SourceScanner.Scan([Path.Combine(_temp.Path, "code")]);

        Assert.Equal([a], scan.Files);
    }

    [UnixFact]
    public void A_fifo_is_skipped_with_a_warning()
    {
        var a = _temp.Write("code/A.cs", "class A { }");
        var fifo = Path.Combine(_temp.Path, "code/Pipe.cs");
        Fifo.Create(fifo);

        var scan = SourceScanner.Scan([Path.Combine(_temp.Path, "code")]);

        Assert.Equal([a], scan.Files);
        var warning = Assert.Single(scan.Skipped).ToString();
        Assert.Matches(@"Pipe\.cs\(1,1\): warning GMAC0411: not a regular file", warning);
    }
}
