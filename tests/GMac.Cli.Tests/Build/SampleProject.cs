using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Build;

/// <summary>
/// A small project in a folder <c>Sample/</c> of a temporary folder that imports the props and
/// targets the GMac.Build package ships (build/GMac.Build.*) and runs the gmac tool built next to
/// the tests (<c>GMacToolPath</c>), with one C# file holding a binding point and a DSL of its own
/// (its <c>.gmac</c> files found by the default glob, the standard library off): the frame, and
/// the macros it uses (<c>Sum</c>, and <c>Third</c>, whose constant shows the scalar type of the code).
/// Other files, also beside the project folder, are added with <see cref="Write"/>.
/// </summary>
internal sealed class SampleProject : IDisposable
{
    private readonly TempFolder _temp = new();

    private const string Folder = "Sample";

    public SampleProject(string kernelsText, string extraProperties = "", string extraItems = "")
    {
        var build = Path.Combine(SharedDsl.RepositoryRoot, "build");
        // Empty Directory.Build files stop MSBuild from importing any found above the temp folder.
        _temp.Write("Directory.Build.props", "<Project />\n");
        _temp.Write("Directory.Build.targets", "<Project />\n");
        ProjectFile = Write("Sample.csproj", $"""
            <Project Sdk="Microsoft.NET.Sdk">
              <Import Project="{Path.Combine(build, "GMac.Build.props")}" />
              <PropertyGroup>
                <TargetFramework>net10.0</TargetFramework>
                <Nullable>enable</Nullable>
                <TreatWarningsAsErrors>true</TreatWarningsAsErrors>
                <GMacStandardLibrary>false</GMacStandardLibrary>
                <GMacToolPath>{ToolPath}</GMacToolPath>
                {extraProperties}
              </PropertyGroup>
              <ItemGroup>
                {extraItems}
              </ItemGroup>
              <Import Project="{Path.Combine(build, "GMac.Build.targets")}" />
            </Project>
            """);
        Write(Path.Combine("dsl", "frame.gmac"), """
            define frame e3d as
                basis: {e1, e2, e3}
                Euclidean
            end frame

            define subspace e3d.vectors as basis {e1, e2, e3} end subspace
            define multivector class e3d.Vector as vectors end multivector class
            """);
        MacroFile = Write(Path.Combine("dsl", "sum.gmac"), """
            define macro Sum as
                inputs: { u : e3d.Vector; v : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
                    w = u + v;
            end macro
            """);
        Write(Path.Combine("dsl", "third.gmac"), """
            define macro Third as
                inputs: { u : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
                    w = (1/3) * u;
            end macro
            """);
        KernelsFile = Write("Kernels.cs", kernelsText);
    }

    public string ProjectFile { get; }

    /// <summary>The gmac tool built with this test assembly.</summary>
    public static string ToolPath => Path.Combine(SharedDsl.RepositoryRoot, "src", "GMac.Cli", "bin", DotnetBuild.Configuration, "net10.0", "gmac.dll");

    /// <summary>The DSL file that defines the macro <c>Sum</c>.</summary>
    public string MacroFile { get; }

    public string KernelsFile { get; }

    /// <summary>The file the MSBuild step touches after each successful generation.</summary>
    public string StampFile => Path.Combine(_temp.Path, Folder, "obj", DotnetBuild.Configuration, "net10.0", "gmac-generate.stamp");

    /// <summary>Writes a file at a path relative to the project folder (it may lead out of it) and returns its full path.</summary>
    public string Write(string path, string text) => Path.GetFullPath(_temp.Write(Path.Combine(Folder, path), text));

    public (int Exit, string Output) Build(bool restore = false) => DotnetBuild.Run(ProjectFile, restore);

    public void Dispose() => _temp.Dispose();
}
