using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.Layering;

/// <summary>
/// Core ← Dsl ← the C# host ← Cli, read from the project files and sources: GMac.Core knows no host
/// language, GMac.Dsl no Roslyn, and only the host reads binding text.
/// </summary>
public sealed class Projects_Layering
{
    [Fact]
    public void Each_project_references_only_the_layer_below()
    {
        Assert.Empty(LayeringRules.ProjectViolations(SharedDsl.RepositoryRoot));
    }

    [Fact]
    public void No_source_outside_the_host_reads_templates_or_uses_roslyn()
    {
        Assert.Empty(LayeringRules.SourceViolations(SharedDsl.RepositoryRoot));
    }

    [Fact]
    public void A_planted_violation_is_caught()
    {
        using var temp = new TempFolder();
        var root = temp.Path;
        foreach (var (name, body) in new[]
        {
            ("GMac.Core", ""),
            ("GMac.Dsl", """<ProjectReference Include="../GMac.Core/GMac.Core.csproj" /><PackageReference Include="Microsoft.CodeAnalysis.CSharp" />"""),
            ("GMac.CSharp", """<ProjectReference Include="../GMac.Dsl/GMac.Dsl.csproj" /><PackageReference Include="Microsoft.CodeAnalysis.CSharp" />"""),
            ("GMac.Cli", """<ProjectReference Include="../GMac.CSharp/GMac.CSharp.csproj" /><ProjectReference Include="../GMac.Core/GMac.Core.csproj" />"""),
        })
        {
            Directory.CreateDirectory(Path.Combine(root, "src", name));
            File.WriteAllText(Path.Combine(root, "src", name, name + ".csproj"), $"<Project><ItemGroup>{body}</ItemGroup></Project>");
        }
        File.WriteAllText(Path.Combine(root, "src", "GMac.Dsl", "Reader.cs"), "var close = text.IndexOf('>', text.IndexOf('<'));\nusing Microsoft.CodeAnalysis;\n");
        File.WriteAllText(Path.Combine(root, "src", "GMac.CSharp", "Host.cs"), "var open = text.IndexOf('<');\nusing Microsoft.CodeAnalysis;\n");

        Assert.Equal(["GMac.Dsl uses package Microsoft.CodeAnalysis.CSharp", "GMac.Cli references project GMac.Core"], LayeringRules.ProjectViolations(root));
        Assert.Equal(["src/GMac.Dsl/Reader.cs(1): '<' reads template text outside the C# host layer", "src/GMac.Dsl/Reader.cs(2): uses Roslyn outside the C# host layer"],
            LayeringRules.SourceViolations(root));
    }
}
