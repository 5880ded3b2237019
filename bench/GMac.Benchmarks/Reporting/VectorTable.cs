using System.Globalization;
using System.Runtime.Intrinsics;
using System.Text;
using GMac.Benchmarks.Applications;

namespace GMac.Benchmarks.Reporting;

/// <summary>The vector section of the report: generated vector code against generated scalar code, and against hand-written vector code.</summary>
public static class VectorTable
{
    /// <summary>
    /// The section: the full table at <paramref name="residentItems"/> items per batch (columns in the L1
    /// cache), the ratios again at <paramref name="largeItems"/>, and the goals at both sizes.
    /// </summary>
    public static string Section(IReadOnlyList<VectorTiming> resident, int residentItems, IReadOnlyList<VectorTiming> large, int largeItems,
        IReadOnlyDictionary<string, (int Columns, int Operations)> traffic, string timing)
    {
        var sb = new StringBuilder();
        void Line(string text = "") => sb.Append(text).Append('\n');
        var has512 = resident.Any(r => r.Vector512Ns is not null);
        var largestKb = traffic.Values.Max(t => t.Columns) * residentItems * sizeof(double) / 1024.0;

        Line("## Vector code");
        Line();
        Line("Each kernel's binding point written as a batch (`//GMac.Batch(\"k\")`, docs/batches.md) over the same inputs in columns, one array per coefficient, " +
             "generated in `Vector256<double>` and `Vector512<double>`, against the kernel's generated scalar code above (one item at a time over its structs). " +
             "Four kernels also have vector code written by hand in `Vector256<double>`, over the same columns. Every column starts on a 64-byte cache line. " +
             $"{timing} Before timing, every vector form was checked item by item against the scalar code (relative 1e-7).");
        Line($"Vector512 in hardware here: {(Vector512.IsHardwareAccelerated ? "yes" : "no (its columns are left empty)")}; Vector256 in hardware: {(Vector256.IsHardwareAccelerated ? "yes" : "no")}.");
        Line();
        Line($"### Batches of {residentItems} items");
        Line();
        Line($"The columns of every kernel fit in the L1 data cache (the largest kernel reads and writes {F(largestKb)} KB), so these times are those of the arithmetic.");
        Line();
        Line("| kernel | scalar ns | Vector256 ns | scalar / Vector256 | Vector512 ns | scalar / Vector512 | hand Vector256 ns | generated / hand Vector256 |");
        Line("|---|---:|---:|---:|---:|---:|---:|---:|");
        foreach (var r in resident)
            Line($"| {r.Kernel} | {F(r.ScalarNs)} | {F(r.Vector256Ns)} | {F2(r.ScalarOver256)} | {F(r.Vector512Ns)} | {F2(r.ScalarOver512)} | {F(r.Hand256Ns)} | {F2(r.GeneratedOverHand256)} |");
        var (mean256, mean512) = Means(resident, has512);
        Line($"| geometric mean | | | {F2(mean256)} | | {F2(mean512)} | | |");
        Line();
        Line($"### Batches of {largeItems} items");
        Line();
        Line("Four times the columns: most kernels now read and write more than the L1 cache holds, and those with few operations per byte " +
             "(the scalar code keeps up with the cache on them, the vector code does not) gain less.");
        Line();
        Line("| kernel | doubles read and written per item | operations (hand count) per double | scalar / Vector256 | scalar / Vector512 | generated / hand Vector256 |");
        Line("|---|---:|---:|---:|---:|---:|");
        foreach (var r in large)
        {
            var (n, ops) = traffic[r.Kernel];
            Line($"| {r.Kernel} | {n} | {F2((double)ops / n)} | {F2(r.ScalarOver256)} | {F2(r.ScalarOver512)} | {F2(r.GeneratedOverHand256)} |");
        }
        var (large256, large512) = Means(large, has512);
        Line($"| geometric mean | | | {F2(large256)} | {F2(large512)} | |");
        Line();
        var hands = resident.Where(r => r.GeneratedOverHand256 is not null).ToArray();
        var overHand = hands.Where(r => r.GeneratedOverHand256 > 1.05).Select(r => $"{r.Kernel} {F2(r.GeneratedOverHand256)}").ToArray();
        Line("| goal | measured | met |");
        Line("|---|---|---|");
        Line($"| scalar / Vector256 ≥ 3 (geometric mean), {residentItems} items | {F2(mean256)} | {YesNo(mean256 >= 3)} |");
        Line(Goal512(mean512, residentItems));
        Line($"| scalar / Vector256 ≥ 3 (geometric mean), {largeItems} items | {F2(large256)} | {YesNo(large256 >= 3)} |");
        Line(Goal512(large512, largeItems));
        Line($"| generated / hand Vector256 ≤ 1.05 on the {hands.Length} hand kernels, {residentItems} items | above 1.05: {(overHand.Length == 0 ? "none" : string.Join(", ", overHand))} | {YesNo(hands.Length > 0 && overHand.Length == 0)} |");
        Line();
        return sb.ToString();
    }


    private static (double Mean256, double? Mean512) Means(IReadOnlyList<VectorTiming> rows, bool has512) =>
        (GeometricMean(rows.Select(r => r.ScalarOver256)), has512 ? GeometricMean(rows.Select(r => r.ScalarOver512!.Value)) : null);

    private static string Goal512(double? mean, int items) => mean is { } m
        ? $"| scalar / Vector512 ≥ 5 (geometric mean), {items} items | {F2(m)} | {YesNo(m >= 5)} |"
        : $"| scalar / Vector512 ≥ 5 (geometric mean), {items} items | no Vector512 in hardware | — |";

    private static double GeometricMean(IEnumerable<double> values) => Math.Exp(values.Average(Math.Log));

    private static string YesNo(bool ok) => ok ? "yes" : "**no**";

    private static string F(double? v) => v is not { } x ? "—" : x.ToString(x >= 100 ? "F0" : x >= 10 ? "F1" : "F2", CultureInfo.InvariantCulture);

    private static string F2(double? v) => v is not { } x ? "—" : x.ToString("F2", CultureInfo.InvariantCulture);
}
