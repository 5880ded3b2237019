using System.Globalization;
using System.Text;
using RayTracer.Geometry.Meshes;
using RayTracer.Scenes.Triangles;

namespace RayTracer.Cli.Experiments;

/// <summary>The Markdown report of the ray–triangle experiment: Table 7-3 re-created, the goals, memory and charts.</summary>
public static class TrianglesReport
{
    public const string ImageFolder = "triangles";

    public static string Write(IReadOnlyList<TrianglesMeasurement> results, IReadOnlyList<TriangleTestScene> scenes, TrianglesSettings settings, string command)
    {
        var text = new StringBuilder();
        void Line(FormattableString line) => text.AppendLine(line.ToString(CultureInfo.InvariantCulture));

        Line($"# Ray–triangle tests under the BIH (thesis §7.2.2, Table 7-3)");
        Line($"");
        Line($"Regenerate with `{command}`.");
        Line($"{Environment.ProcessorCount} logical processors; {settings.Width}×{settings.Height} pixels, 1 sample per pixel, {settings.Threads} render thread(s), best of {settings.Repeats} run(s); mesh detail {settings.Detail} of the thesis's counts.");
        Line($"");
        Line($"Four tests: `moller` (Möller–Trumbore), `algebraic` (Cramer's rule, the base book's test), `plucker` (generated from `PluckerRayTriangle`, edge lines built per test from the vertices) and `plucker-edges` (generated from `PluckerRayTriangleLines`, on three edge lines and the plane stored per triangle).");
        Line($"*Render* is the whole render (the thesis's total test time): everything but the triangle test is the same, so differences come from the test. *Nearest hit* times BIH nearest-hit queries alone for {settings.NearestHitRays:N0} rays from the eye to random points of the mesh's bounds. Times are the best of the runs, which take the four tests in turn round after round; CPU time (of the whole process) is given besides wall time because the machine may be shared, and the ratios below use CPU time. *Bytes/triangle* is the heap that the triangle objects, their packed test data and the BIH keep alive (measured with full collections around their construction; shared vertices and normals excluded). *Image* compares each render with Möller–Trumbore's: the largest channel difference in linear radiance and the pixels that differ at all.");
        Line($"");
        Line($"| scene (thesis) | test | triangles | rays | test invocations | render (ms) | nearest hit (ms) | bytes/triangle | image vs moller |");
        Line($"|---|---|---:|---:|---:|---:|---:|---:|---|");
        foreach (var scene in scenes)
        {
            foreach (var r in results.Where(r => r.Scene == scene.Name))
            {
                var image = r.Test == TriangleTest.MollerTrumbore ? "reference" : $"max {r.MaxPixelDifference:0.###e0}, {r.DifferingPixels} px";
                Line($"| {scene.Name} ({scene.ThesisScene}, {scene.ThesisTriangles:N0}) | {r.Test.Name()} | {r.Triangles:N0} | {r.Rays:N0} | {r.TestInvocations:N0} | {r.RenderCpuTime.TotalMilliseconds:F0} | {r.RenderTime.TotalMilliseconds:F0} | {r.NearestHitCpuTime.TotalMilliseconds:F0} | {r.NearestHitTime.TotalMilliseconds:F0} | {r.BytesPerTriangle:F0} | {image} |");
            }
        }

        Line($"");
        Line($"## Goals");
        Line($"");
        Line($"Ratios of render CPU time (and of nearest-hit CPU time) in this run. Goals: Plücker at least as fast as the algebraic test (P/A ≤ 1) and within 1.1× of Möller–Trumbore (P/M ≤ 1.1).");
        Line($"");
        Line($"| scene | plucker P/A | plucker P/M | plucker-edges P/A | plucker-edges P/M | nearest hit: plucker P/A, P/M | plucker-edges P/A, P/M |");
        Line($"|---|---:|---:|---:|---:|---:|---:|");
        foreach (var scene in scenes)
        {
            double Ratio(TriangleTest p, TriangleTest q, Func<TrianglesMeasurement, TimeSpan> time) =>
                time(TrianglesCharts.Find(results, scene.Name, p)).TotalSeconds / time(TrianglesCharts.Find(results, scene.Name, q)).TotalSeconds;
            string Mark(double ratio, double limit) => ratio <= limit ? $"{ratio:F3}" : $"**{ratio:F3}** (missed)";
            Func<TrianglesMeasurement, TimeSpan> render = r => r.RenderCpuTime, nearest = r => r.NearestHitCpuTime;
            Line($"| {scene.Name} | {Mark(Ratio(TriangleTest.Plucker, TriangleTest.Algebraic, render), 1)} | {Mark(Ratio(TriangleTest.Plucker, TriangleTest.MollerTrumbore, render), 1.1)} | {Mark(Ratio(TriangleTest.PluckerEdges, TriangleTest.Algebraic, render), 1)} | {Mark(Ratio(TriangleTest.PluckerEdges, TriangleTest.MollerTrumbore, render), 1.1)} | {Ratio(TriangleTest.Plucker, TriangleTest.Algebraic, nearest):F3}, {Ratio(TriangleTest.Plucker, TriangleTest.MollerTrumbore, nearest):F3} | {Ratio(TriangleTest.PluckerEdges, TriangleTest.Algebraic, nearest):F3}, {Ratio(TriangleTest.PluckerEdges, TriangleTest.MollerTrumbore, nearest):F3} |");
        }

        Line($"");
        Line($"![render time relative to Möller–Trumbore]({ImageFolder}/render-time.png)");
        Line($"");
        Line($"![nearest-hit time relative to Möller–Trumbore]({ImageFolder}/nearest-hit-time.png)");
        Line($"");
        Line($"![gain of the Plücker test over the algebraic test]({ImageFolder}/plucker-gain.png)");
        Line($"");
        Line($"## Memory per triangle");
        Line($"");
        Line($"The packed data a BIH leaf tests: 72 bytes for `moller`, `algebraic` (v0 and two edges) and `plucker` (three vertices); 176 bytes for `plucker-edges` (three 6-coefficient lines and a 4-coefficient plane). The measured totals above add the triangle objects and the BIH nodes, which all tests share.");
        Line($"");
        foreach (var test in TrianglesExperiment.Tests)
        {
            var perTriangle = results.Where(r => r.Test == test).Select(r => r.BytesPerTriangle).ToArray();
            Line($"- `{test.Name()}`: {perTriangle.Min():F0} to {perTriangle.Max():F0} bytes per triangle over the five scenes.");
        }

        Line($"");
        Line($"## Generated code against a hand-written Plücker test");
        Line($"");
        Line($"Counts printed by `gmac show MACRO --dsl dsl --stats` for the bindings in `src/RayTracer/Geometry/Solvers/PluckerTriangleSolver.cs`, next to the same steps written by hand (ray line o × d; each edge line b − a, a × b; each side d · m + m_r · (b − a); plane normal e1 × e2 and its offset):");
        Line($"");
        Line($"| step | generated (add/sub, mul) | by hand (add/sub, mul) |");
        Line($"|---|---|---|");
        Line($"| `plucker`: d1, d2 (before the first exit) | 25, 29 | 27, 30 |");
        Line($"| `plucker`: d3 and the t numerator | 27, 21 | 20, 24 (ray line again, edge, side, normal, offset) |");
        Line($"| `plucker-edges`: ray line | 3, 6 | 3, 6 |");
        Line($"| `plucker-edges`: d1, d2 | 10, 12 | 10, 12 |");
        Line($"| `plucker-edges`: d3 and the t numerator | 8, 9 | 8, 9 |");
        Line($"| Möller–Trumbore, for scale (full path) | 17, 27 and a division | |");
        Line($"");
        Line($"## Images (Möller–Trumbore renders; the other tests' differences are in the table)");
        Line($"");
        foreach (var scene in scenes)
            Line($"- {scene.Name}, standing for the thesis's {scene.ThesisScene}: {scene.Description}.\n\n  ![{scene.Name}]({ImageFolder}/{scene.Name}.png)\n");
        return text.ToString();
    }
}
