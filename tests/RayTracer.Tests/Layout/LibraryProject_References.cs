using System.Xml.Linq;
using RayTracer.Maths;

namespace RayTracer.Tests.Layout;

/// <summary>
/// The ray tracer library (src/RayTracer) holds no command line and draws no charts: those belong to the
/// raytracer application (src/RayTracer.App) on top of it. Read from the project files (the library's and,
/// through its project references, every project it builds on) and from the compiled library.
/// </summary>
public class LibraryProject_References
{
    private static readonly string[] ForbiddenPackagePrefixes =
        ["System.CommandLine", "ScottPlot", "SkiaSharp", "Spectre", "OxyPlot"];

    private static bool IsForbidden(string name) =>
        ForbiddenPackagePrefixes.Any(prefix => name.StartsWith(prefix, StringComparison.OrdinalIgnoreCase));

    [Fact]
    public void Library_and_the_projects_it_references_name_no_command_line_or_charting_package()
    {
        var library = Path.Combine(RepositoryRoot(), "src", "RayTracer", "RayTracer.csproj");
        var offending = new List<string>();
        var projects = ProjectClosure(library);
        foreach (var project in projects)
        {
            foreach (var package in XDocument.Load(project).Descendants("PackageReference"))
            {
                var name = (string?)package.Attribute("Include") ?? (string?)package.Attribute("Update") ?? "";
                if (IsForbidden(name)) offending.Add($"{Path.GetFileName(project)}: {name}");
            }
        }
        Assert.Contains(projects, p => p.EndsWith(Path.Combine("Twister", "Twister.csproj"), StringComparison.Ordinal));
        Assert.Empty(offending);
    }

    [Fact]
    public void Library_builds_on_no_executable_project_so_not_on_the_application()
    {
        var library = Path.Combine(RepositoryRoot(), "src", "RayTracer", "RayTracer.csproj");
        var executables = ProjectClosure(library)
            .Where(p => XDocument.Load(p).Descendants("OutputType").Any(e => e.Value.Trim() == "Exe"))
            .ToList();
        Assert.Empty(executables);
    }

    [Fact]
    public void Compiled_library_loads_no_command_line_or_charting_assembly()
    {
        var library = typeof(Vector3D).Assembly;
        Assert.Equal("RayTracer.Core", library.GetName().Name);
        var offending = library.GetReferencedAssemblies()
            .Select(a => a.Name ?? "")
            .Where(name => IsForbidden(name) || name.Equals("raytracer", StringComparison.OrdinalIgnoreCase))
            .ToList();
        Assert.Empty(offending);
        Assert.DoesNotContain(library.GetTypes(), t => t.Namespace is { } ns && ns.StartsWith("RayTracer.Cli", StringComparison.Ordinal));
    }

    /// <summary>The project and every project it references, directly or not (GMac.Cli's build-only reference aside).</summary>
    private static List<string> ProjectClosure(string project)
    {
        var seen = new List<string>();
        var pending = new Stack<string>([Path.GetFullPath(project)]);
        while (pending.Count > 0)
        {
            var next = pending.Pop();
            if (seen.Contains(next)) continue;
            seen.Add(next);
            var folder = Path.GetDirectoryName(next)!;
            foreach (var reference in XDocument.Load(next).Descendants("ProjectReference"))
            {
                var include = (string?)reference.Attribute("Include");
                if (include is null || include.Contains("$(", StringComparison.Ordinal)) continue;
                pending.Push(Path.GetFullPath(Path.Combine(folder, include.Replace('\\', Path.DirectorySeparatorChar))));
            }
        }
        return seen;
    }

    private static string RepositoryRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
            if (File.Exists(Path.Combine(dir.FullName, "GMac.sln"))) return dir.FullName;
        throw new InvalidOperationException("GMac.sln not found above the test assembly.");
    }
}
