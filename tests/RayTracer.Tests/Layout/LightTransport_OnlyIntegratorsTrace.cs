using System.Text.RegularExpressions;

namespace RayTracer.Tests.Layout;

/// <summary>
/// Light transport lives in the integrators (src/RayTracer/Integrators): materials give BSDFs, lights give
/// radiance and samples, and nothing else traces. Read from the source files of the library and of the
/// application, so that a material or light that casts a ray fails here rather than in an image.
/// </summary>
public partial class LightTransport_OnlyIntegratorsTrace
{
    // Radiance along a ray: the integrator's entry points, reached directly or through the world.
    [GeneratedRegex(@"\bTrace(Ray|Spawned|Specular|Bounce)\s*\(|\.(Tracer|Integrator)\s*!?\s*\.(?!RenderPixel\b)")]
    private static partial Regex TracerCall();

    // The world's queries (nearest hit, shadow ray); an object's own ShadowHit(ray, out t) is geometry.
    [GeneratedRegex(@"(?<!bool )\b(HitObjects|ShadowHit)\s*\((?!.*\bout\b)")]
    private static partial Regex WorldRayQuery();

    [Fact]
    public void No_file_outside_the_integrators_traces_a_ray_or_casts_a_shadow_ray()
    {
        var root = RepositoryRoot();
        var integrators = Path.Combine(root, "src", "RayTracer", "Integrators") + Path.DirectorySeparatorChar;
        var offending = new List<string>();
        foreach (var project in new[] { "RayTracer", "RayTracer.App" })
        {
            var folder = Path.Combine(root, "src", project);
            foreach (var file in Directory.EnumerateFiles(folder, "*.cs", SearchOption.AllDirectories))
            {
                if (file.StartsWith(integrators, StringComparison.Ordinal) || IsBuildOutput(file))
                    continue;
                var lines = File.ReadAllLines(file);
                for (var i = 0; i < lines.Length; i++)
                {
                    var code = StripComment(lines[i]);
                    if (TracerCall().IsMatch(code) || WorldRayQuery().IsMatch(code))
                        offending.Add($"{Path.GetRelativePath(root, file)}:{i + 1}: {code.Trim()}");
                }
            }
        }
        Assert.True(offending.Count == 0, "only integrators trace:\n" + string.Join('\n', offending));
    }

    [Fact]
    public void The_patterns_catch_the_calls_they_stand_for()
    {
        Assert.Matches(TracerCall(), "return fr * sr.World!.Tracer!.TraceSpawned(sr, ray, fr);");
        Assert.Matches(TracerCall(), "sum += tracer.TraceRay(ray, 0);");
        Assert.Matches(WorldRayQuery(), "sr.World is { } world && world.ShadowHit(ray, distance);");
        Assert.DoesNotMatch(WorldRayQuery(), "return Target.ShadowHit(ToLocal(ray), out tmin);");
        Assert.DoesNotMatch(WorldRayQuery(), "public bool ShadowHit(in Ray ray, double maxDistance)");
        Assert.DoesNotMatch(TracerCall(), "image[column, row] = integrator.RenderPixel(camera, column, row);");
    }

    private static string StripComment(string line)
    {
        var trimmed = line.TrimStart();
        if (trimmed.StartsWith("//", StringComparison.Ordinal) || trimmed.StartsWith('*'))
            return "";
        var comment = line.IndexOf("//", StringComparison.Ordinal);
        return comment >= 0 ? line[..comment] : line;
    }

    private static bool IsBuildOutput(string file) =>
        file.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", StringComparison.Ordinal)
        || file.Contains($"{Path.DirectorySeparatorChar}bin{Path.DirectorySeparatorChar}", StringComparison.Ordinal);

    private static string RepositoryRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
            if (File.Exists(Path.Combine(dir.FullName, "GMac.sln"))) return dir.FullName;
        throw new InvalidOperationException("GMac.sln not found above the test assembly.");
    }
}
