using System.Globalization;
using System.Runtime.Intrinsics;
using System.Text;
using GMac.Benchmarks.Applications;

namespace GMac.Benchmarks.Reporting;

/// <summary>The vector section of the report: generated vector code against generated scalar code, and against hand-written vector code.</summary>
public static class VectorTable
{
    public static string Section(IReadOnlyList<VectorTiming> rows, string timing)
    {
        var sb = new StringBuilder();
        void Line(string text = "") => sb.Append(text).Append('\n');
        var has512 = rows.Any(r => r.Vector512Ns is not null);

        Line("## Vector code");
        Line();
        Line("Each kernel's binding point written as a batch (`//GMac.Batch(\"k\")`, docs/batches.md) over the same inputs in columns, one array per coefficient, " +
             "generated in `Vector256<double>` and `Vector512<double>`, against the kernel's generated scalar code above (one item at a time over its structs). " +
             "Four kernels also have vector code written by hand in `Vector256<double>`, over the same columns. " +
             $"{timing} Before timing, every vector form was checked item by item against the scalar code (relative 1e-7).");
        Line($"Vector512 in hardware here: {(Vector512.IsHardwareAccelerated ? "yes" : "no (its columns are left empty)")}; Vector256 in hardware: {(Vector256.IsHardwareAccelerated ? "yes" : "no")}.");
        Line();
        Line("| kernel | scalar ns | Vector256 ns | scalar / Vector256 | Vector512 ns | scalar / Vector512 | hand Vector256 ns | generated / hand Vector256 |");
        Line("|---|---:|---:|---:|---:|---:|---:|---:|");
        foreach (var r in rows)
            Line($"| {r.Kernel} | {F(r.ScalarNs)} | {F(r.Vector256Ns)} | {F2(r.ScalarOver256)} | {F(r.Vector512Ns)} | {F2(r.ScalarOver512)} | {F(r.Hand256Ns)} | {F2(r.GeneratedOverHand256)} |");
        var mean256 = GeometricMean(rows.Select(r => r.ScalarOver256));
        var mean512 = has512 ? GeometricMean(rows.Select(r => r.ScalarOver512!.Value)) : (double?)null;
        Line($"| geometric mean | | | {F2(mean256)} | | {F2(mean512)} | | |");
        Line();
        var hands = rows.Where(r => r.GeneratedOverHand256 is not null).ToArray();
        var overHand = hands.Where(r => r.GeneratedOverHand256 > 1.05).Select(r => $"{r.Kernel} {F2(r.GeneratedOverHand256)}").ToArray();
        Line("| goal | measured | met |");
        Line("|---|---|---|");
        Line($"| scalar / Vector256 ≥ 3 (geometric mean) | {F2(mean256)} | {YesNo(mean256 >= 3)} |");
        Line(mean512 is { } m512 ? $"| scalar / Vector512 ≥ 5 (geometric mean) | {F2(m512)} | {YesNo(m512 >= 5)} |" : "| scalar / Vector512 ≥ 5 (geometric mean) | no Vector512 in hardware | — |");
        Line($"| generated / hand Vector256 ≤ 1.05 on the {hands.Length} hand kernels | above 1.05: {(overHand.Length == 0 ? "none" : string.Join(", ", overHand))} | {YesNo(hands.Length > 0 && overHand.Length == 0)} |");
        Line();
        return sb.ToString();
    }

    private static double GeometricMean(IEnumerable<double> values) => Math.Exp(values.Average(Math.Log));

    private static string YesNo(bool ok) => ok ? "yes" : "**no**";

    private static string F(double? v) => v is not { } x ? "—" : x.ToString(x >= 100 ? "F0" : x >= 10 ? "F1" : "F2", CultureInfo.InvariantCulture);

    private static string F2(double? v) => v is not { } x ? "—" : x.ToString("F2", CultureInfo.InvariantCulture);
}
