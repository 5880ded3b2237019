using System.Globalization;
using System.Text;
using RayTracer.Scenes.Instancing;
using RayTracer.Timing;

namespace RayTracer.Cli.Experiments;

/// <summary>The Markdown of the instancing experiment: Table 7-2, the goals as measured, agreement, charts and images.</summary>
internal static class InstancingReport
{
    public static string Write(IReadOnlyList<InstancingMeasurement> results, string command, InstancingExperiment run,
        string imageFolder, IReadOnlySet<string> writtenImages)
    {
        var methods = Enum.GetValues<CylinderMethod>();
        var scenes = results.Select(r => r.Scene).Distinct().ToList();
        InstancingMeasurement At(string scene, CylinderMethod method) => results.Single(r => r.Scene == scene && r.Method == method);

        var md = new StringBuilder();
        md.AppendLine("# Instancing performance (thesis §7.2.1, Table 7-2)");
        md.AppendLine();
        md.Append(Invariant($"Regenerate with `{command}`. One run: {run.Width}×{run.Height} pixels, one sample per pixel, "));
        md.Append(Invariant($"the fastest of {run.Repeats} timed replay(s) of the tests per scene and method, renders on {run.Threads} thread(s), "));
        md.AppendLine(Invariant($"{Environment.ProcessorCount} logical cores, .NET {Environment.Version}, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}."));
        md.AppendLine();
        md.AppendLine("The five ways to place a cylinder: **U-Cyl** the hand-derived universal cylinder; **GAU-Cyl** a universal " +
            "cylinder whose intersection has RSTR instancing folded in when the kernel is generated; **I-Cyl** a 4×4-matrix " +
            "instance of the generic tube; **TSR-Cyl** a TSR instance (12 coefficients) and **RSTR-Cyl** an RSTR instance " +
            "(a point and a mirror normal) of the same tube. Every tube is open, as in the generic tube.");
        md.AppendLine();
        md.Append("Rays are every ray cast (primary, reflected, shadow). Test invocations are the calls on tubes (nearest-hit, " +
            "shading and shadow tests), counted per method in a render on one thread that also records each call; instances " +
            "have looser bounding boxes (the box of the moved local box), so the hierarchy asks them more often. The test time " +
            "is the time of exactly those calls asked again of the bare tubes, in order, on one thread: the tests alone, " +
            (ThreadCpuClock.IsThreadTime ? "in the thread's CPU time (time spent waiting for a core is not counted), " : "in wall time, ") +
            "without traversal and shading. The render time is the wall time of one whole render of the bare tubes, for comparison " +
            "(it moves with the load of the machine). Memory is measured: ");
        md.AppendLine(Invariant($"{run.MemorySamples} and {2 * run.MemorySamples} tubes of the scene built and kept, the heap weighed after full collections before and after, ") +
            Invariant($"and the difference of the two divided by {run.MemorySamples}; shared materials are not counted."));
        md.AppendLine();

        md.Append("| | |");
        foreach (var scene in scenes) md.Append(Invariant($" {Title(scene)} |"));
        md.AppendLine();
        md.Append("|---|---|");
        foreach (var _ in scenes) md.Append("---:|");
        md.AppendLine();
        Row(md, "**Total cylinders**", "", scenes.Select(s => At(s, CylinderMethod.UCyl).Objects.ToString("N0", CultureInfo.InvariantCulture)));
        Row(md, "**Total rays**", "", scenes.Select(s => At(s, CylinderMethod.UCyl).Rays.ToString("N0", CultureInfo.InvariantCulture)));
        foreach (var method in methods)
            Row(md, method == methods[0] ? "**Total test invocations**" : "", InstancingExperiment.Label(method),
                scenes.Select(s => At(s, method).TestInvocations.ToString("N0", CultureInfo.InvariantCulture)));
        foreach (var method in methods)
            Row(md, method == methods[0] ? "**Total test time (ms)**" : "", InstancingExperiment.Label(method),
                scenes.Select(s => At(s, method).TimeMilliseconds.ToString("N1", CultureInfo.InvariantCulture)));
        foreach (var method in methods)
            Row(md, method == methods[0] ? "**Render time (ms)**" : "", InstancingExperiment.Label(method),
                scenes.Select(s => At(s, method).RenderMilliseconds.ToString("N0", CultureInfo.InvariantCulture)));
        foreach (var method in methods)
            Row(md, method == methods[0] ? "**Total cylinder memory (KB)**" : "", InstancingExperiment.Label(method),
                scenes.Select(s => At(s, method).TotalKilobytes.ToString("N3", CultureInfo.InvariantCulture)));
        foreach (var method in methods)
            Row(md, method == methods[0] ? "**Bytes per cylinder**" : "", InstancingExperiment.Label(method),
                scenes.Select(s => At(s, method).BytesPerObject.ToString("N0", CultureInfo.InvariantCulture)));
        md.AppendLine();

        md.AppendLine("## Goals, as measured in this run");
        md.AppendLine();
        var gauFastest = scenes.Where(s => methods.All(m => m == CylinderMethod.GauCyl ||
            At(s, CylinderMethod.GauCyl).TimeMilliseconds < At(s, m).TimeMilliseconds)).ToList();
        md.AppendLine(Invariant($"- GAU-Cyl fastest of the five in test time: {Verdict(gauFastest, scenes)}."));
        foreach (var method in new[] { CylinderMethod.TsrCyl, CylinderMethod.RstrCyl })
        {
            var faster = scenes.Where(s => At(s, method).TimeMilliseconds < At(s, CylinderMethod.ICyl).TimeMilliseconds).ToList();
            var smaller = scenes.Where(s => At(s, method).BytesPerObject < At(s, CylinderMethod.ICyl).BytesPerObject).ToList();
            md.AppendLine(Invariant($"- {InstancingExperiment.Label(method)} faster than I-Cyl in test time: {Verdict(faster, scenes)}; smaller per cylinder: {Verdict(smaller, scenes)}."));
        }

        md.AppendLine();
        md.AppendLine("Gain in test time, (baseline − method) / baseline, per scene (Figures 7-6 and 7-7):");
        md.AppendLine();
        md.Append("| |");
        foreach (var scene in scenes) md.Append(Invariant($" {Title(scene)} |"));
        md.AppendLine();
        md.Append("|---|");
        foreach (var _ in scenes) md.Append("---:|");
        md.AppendLine();
        foreach (var (label, method, baseline) in Gains)
        {
            md.Append(Invariant($"| {label} |"));
            foreach (var scene in scenes)
                md.Append(Invariant($" {Gain(At(scene, method), At(scene, baseline)):F1} % |"));
            md.AppendLine();
        }

        md.AppendLine();
        md.AppendLine("## Agreement");
        md.AppendLine();
        md.AppendLine(Invariant($"Every render is compared with U-Cyl's, pixel by pixel, after tone mapping to 8 bits: the largest difference of any channel, and the pixels that differ by more than {InstancingExperiment.PixelTolerance}."));
        md.AppendLine();
        md.Append("| method |");
        foreach (var scene in scenes) md.Append(Invariant($" {Title(scene)} |"));
        md.AppendLine();
        md.Append("|---|");
        foreach (var _ in scenes) md.Append("---:|");
        md.AppendLine();
        foreach (var method in methods.Skip(1))
        {
            md.Append(Invariant($"| {InstancingExperiment.Label(method)} |"));
            foreach (var scene in scenes)
            {
                var r = At(scene, method);
                md.Append(Invariant($" max {r.MaxPixelDifference}, {r.PixelsOverTolerance} over |"));
            }

            md.AppendLine();
        }

        md.AppendLine();
        md.AppendLine("## Charts");
        md.AppendLine();
        md.AppendLine(Invariant($"![Total test time]({imageFolder}/time.png)"));
        md.AppendLine();
        md.AppendLine(Invariant($"![Total cylinder memory]({imageFolder}/memory.png)"));
        md.AppendLine();
        md.AppendLine(Invariant($"![Gain in time]({imageFolder}/gain.png)"));
        md.AppendLine();
        md.AppendLine("## Scenes (Figure 7-3)");
        md.AppendLine();
        md.AppendLine("Rendered with U-Cyl; a method's own render is shown too when it differs beyond the tolerance.");
        md.AppendLine();
        foreach (var scene in scenes)
        {
            md.AppendLine(Invariant($"![{Title(scene)}]({imageFolder}/{scene}.png)"));
            foreach (var method in methods)
                if (writtenImages.Contains(ImageName(scene, method)))
                    md.AppendLine(Invariant($"![{Title(scene)}, {InstancingExperiment.Label(method)}]({imageFolder}/{ImageName(scene, method)}.png)"));
            md.AppendLine();
        }

        return md.ToString();
    }

    public static readonly (string Label, CylinderMethod Method, CylinderMethod Baseline)[] Gains =
    [
        ("GAU-Cyl over U-Cyl", CylinderMethod.GauCyl, CylinderMethod.UCyl),
        ("TSR-Cyl over I-Cyl", CylinderMethod.TsrCyl, CylinderMethod.ICyl),
        ("RSTR-Cyl over I-Cyl", CylinderMethod.RstrCyl, CylinderMethod.ICyl),
    ];

    public static double Gain(InstancingMeasurement method, InstancingMeasurement baseline) =>
        100 * (baseline.TimeMilliseconds - method.TimeMilliseconds) / baseline.TimeMilliseconds;

    public static string ImageName(string scene, CylinderMethod method) =>
        $"{scene}-{InstancingExperiment.Label(method).ToLowerInvariant()}";

    public static string Title(string scene) => scene switch
    {
        "instancing-blocks" => "Blocks",
        "instancing-helix" => "Helix",
        "instancing-epitrochoid" => "Epitrochoid",
        "instancing-column" => "Column",
        _ => scene,
    };

    private static void Row(StringBuilder md, string head, string method, IEnumerable<string> cells)
    {
        md.Append(Invariant($"| {head} | {method} |"));
        foreach (var cell in cells) md.Append(Invariant($" {cell} |"));
        md.AppendLine();
    }

    private static string Verdict(List<string> met, List<string> scenes) =>
        met.Count == scenes.Count
            ? "met on every scene"
            : Invariant($"**missed** on {string.Join(", ", scenes.Except(met).Select(Title))}");

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
