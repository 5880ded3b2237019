using System.Globalization;
using System.Text;
using GMac.Benchmarks.Accuracy;

namespace GMac.Benchmarks.Reporting;

/// <summary>The accuracy section of <c>ga-apps.md</c>: generated and hand errors per kernel and input family.</summary>
public static class AccuracyTable
{
    public static string GoalRow(IReadOnlyList<AccuracyRow> rows)
    {
        var missed = rows.Where(r => !r.Met).Select(r => $"{r.Kernel} {r.Family.Name} {Ratio(r)}").ToArray();
        var worst = rows.MaxBy(r => r.Ratio)!;
        return $"| generated error within 10× of hand on every kernel and input family | worst {worst.Kernel} {worst.Family.Name} {Ratio(worst)}; " +
               $"above 10×: {(missed.Length == 0 ? "none" : string.Join(", ", missed))} | {(missed.Length == 0 ? "yes" : "**no**")} |";
    }

    public static string Section(IReadOnlyList<AccuracyRow> rows, int itemsPerFamily, int seed)
    {
        var sb = new StringBuilder();
        void Line(string text = "") => sb.Append(text).Append('\n');
        Line("## Accuracy");
        Line();
        Line($"Each kernel runs on {itemsPerFamily} inputs of each family (seed {seed}): its random inputs and ill-conditioned ones. " +
             "The reference is exact: the kernel's binding point generated from `dsl/` and evaluated on rationals (math functions to 200 bits), " +
             "on the very doubles the variants were given. The error of an item is normwise: the largest error of a component over the largest component of the exact output. " +
             $"The ratio compares the worst items, each at least {AccuracyRow.Floor:0.0e0} (two units of 2⁻⁵²).");
        Line();
        Line("| kernel | family | inputs | generated median | generated max | hand median | hand max | generated / hand | within 10× |");
        Line("|---|---|---|---:|---:|---:|---:|---:|---|");
        foreach (var r in rows)
            Line($"| {r.Kernel} | {r.Family.Name} | {r.Family.Description} | {E(r.GeneratedMedian)} | {E(r.GeneratedMax)} | {E(r.HandMedian)} | {E(r.HandMax)} | {Ratio(r)} | {(r.Met ? "yes" : "**no**")} |");
        Line();
        return sb.ToString();
    }

    private static string Ratio(AccuracyRow r) => r.Ratio.ToString(r.Ratio >= 100 ? "0" : "0.0", CultureInfo.InvariantCulture);

    private static string E(double v) => v == 0 ? "0" : v.ToString("0.0e0", CultureInfo.InvariantCulture);
}
