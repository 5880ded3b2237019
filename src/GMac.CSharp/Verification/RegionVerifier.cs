using System.Globalization;
using System.Text.RegularExpressions;
using GMac.Core.Numerics;
using GMac.Dsl;
using GMac.Dsl.Generation;
using GMac.Dsl.Semantics;

namespace GMac.CSharp.Verification;

/// <summary>
/// Runs a compiled region on seeded random inputs and compares every output with the macro
/// evaluated on doubles by the numeric engine (an independent path through the algebra).
/// </summary>
internal static partial class RegionVerifier
{
    public const double Tolerance = 1e-9;

    /// <summary>Finite differences (macros using <c>diff</c>) agree with exact derivatives only to about this.</summary>
    public const double DifferentiationTolerance = 1e-4;

    /// <summary>
    /// Float code keeps about 7 digits; after the cancellations of a typical kernel (sums of
    /// products of inputs near 1) a few more go, so float regions are held to 1e-4, some
    /// thousand float roundings: far tighter than any wrong formula, far looser than rounding.
    /// </summary>
    public const double SingleTolerance = 1e-4;

    /// <summary>The tolerance for a region: its macro's (exact or differentiated) widened to float accuracy for float code.</summary>
    public static double ToleranceFor(bool differentiates, bool single) =>
        Math.Max(differentiates ? DifferentiationTolerance : Tolerance, single ? SingleTolerance : 0.0);

    /// <summary>
    /// A vector kernel (<see cref="CompiledKernel.Lanes"/> above one) gets a different sample in every
    /// lane, and every lane is compared with the engine on its own sample.
    /// </summary>
    public static VerificationResult Verify(CompiledKernel kernel, BindingPointPlan plan, IReadOnlyList<AssumptionSpec> assumptions,
        IReadOnlyList<IReadOnlyList<string>> normalizedGroups, double tolerance, int seed, int samples = 5)
    {
        var random = new Random(seed);
        var bounds = Bounds(plan, assumptions);
        var lanes = kernel.Lanes;
        // Whole vectors of samples: at least as many as asked for, every lane filled.
        var wanted = (samples + lanes - 1) / lanes * lanes;
        var input = new double[kernel.Inputs.Count * lanes];
        var output = new double[kernel.Outputs.Count * lanes];
        var batch = new List<(Dictionary<string, double> Values, IReadOnlyDictionary<string, double> Reference)>();
        var compared = 0;
        var maxError = 0.0;
        // Some inputs are singular (a zero norm, a degenerate sphere): try more points than needed.
        for (var attempt = 0; attempt < wanted * 4 && compared < wanted; attempt++)
        {
            var values = new Dictionary<string, double>(StringComparer.Ordinal);
            foreach (var name in plan.InputTexts.Keys)
            {
                var (low, high) = bounds.TryGetValue(name, out var b) ? b : (-1.5, 1.5);
                values[name] = low + (high - low) * random.NextDouble();
            }
            foreach (var group in normalizedGroups)
            {
                var norm = Math.Sqrt(group.Sum(n => values[n] * values[n]));
                if (norm > 0) foreach (var n in group) values[n] /= norm;
            }
            // A float kernel sees its inputs rounded to float; the reference gets the same inputs.
            if (kernel.IsSingle) foreach (var name in values.Keys.ToList()) values[name] = (float)values[name];
            var reference = plan.NumericReference(values);
            if (reference.Values.Any(v => !double.IsFinite(v))) continue;
            batch.Add((values, reference));
            if (batch.Count < lanes) continue;
            for (var l = 0; l < lanes; l++)
            for (var i = 0; i < kernel.Inputs.Count; i++)
                input[i * lanes + l] = batch[l].Values.TryGetValue(kernel.Inputs[i], out var v) ? v : 0.0;
            Array.Fill(output, double.NaN);
            kernel.Run(input, output);
            for (var l = 0; l < lanes; l++)
            {
                compared++;
                for (var j = 0; j < kernel.Outputs.Count; j++)
                {
                    var actual = output[j * lanes + l];
                    var expected = batch[l].Reference.TryGetValue(kernel.Outputs[j], out var r) ? r : 0.0;
                    var error = Math.Abs(actual - expected) / Math.Max(1.0, Math.Max(Math.Abs(expected), Math.Abs(actual)));
                    if (double.IsNaN(error)) error = double.PositiveInfinity;
                    maxError = Math.Max(maxError, error);
                    if (error > tolerance)
                        return new VerificationResult(compared, maxError, tolerance, string.Create(CultureInfo.InvariantCulture,
                            $"output '{kernel.Outputs[j]}' is {actual:R} but the numeric engine gives {expected:R} (sample {compared}{(lanes > 1 ? $", lane {l}" : "")}, inputs {string.Join(", ", batch[l].Values.Select(x => $"{plan.InputTexts[x.Key]}={x.Value:G6}"))})"));
                }
            }
            batch.Clear();
        }
        return compared == 0
            ? new VerificationResult(0, 0, tolerance, "no sample gave finite reference values")
            : new VerificationResult(compared, maxError, tolerance, null);
    }

    /// <summary>Sampling ranges that respect the binding point's AssumeMin/AssumeMax.</summary>
    private static Dictionary<string, (double, double)> Bounds(BindingPointPlan plan, IReadOnlyList<AssumptionSpec> assumptions)
    {
        var bounds = new Dictionary<string, (double, double)>(StringComparer.Ordinal);
        foreach (var (name, text) in plan.InputTexts)
        {
            var mins = assumptions.Where(a => a.IsMinimum && a.Expression.Trim() == text.Trim()).Select(a => a.Value.ToDouble()).ToList();
            var maxs = assumptions.Where(a => !a.IsMinimum && a.Expression.Trim() == text.Trim()).Select(a => a.Value.ToDouble()).ToList();
            if (mins.Count == 0 && maxs.Count == 0) continue;
            var low = mins.Count > 0 ? mins.Max() : maxs.Min() - 3.0;
            var high = maxs.Count > 0 ? maxs.Min() : low + 3.0;
            bounds[name] = (low, high);
        }
        return bounds;
    }

    /// <summary>Whether the macro or any macro it calls differentiates (its reference then uses finite differences).</summary>
    public static bool UsesDifferentiation(DslProject project, MacroSymbol macro, HashSet<MacroSymbol>? seen = null)
    {
        seen ??= [];
        if (!seen.Add(macro)) return false;
        var tree = project.SyntaxTrees.FirstOrDefault(t => t.FilePath == macro.Declaration.FilePath);
        if (tree is not null)
        {
            var start = Math.Clamp(macro.Declaration.Start, 0, tree.Text.Length);
            var end = tree.Text.IndexOf("end macro", start, StringComparison.Ordinal);
            if (Differentiation().IsMatch(tree.Text[start..(end < 0 ? tree.Text.Length : end)])) return true;
        }
        return macro.Callees.Any(c => UsesDifferentiation(project, c, seen));
    }

    [GeneratedRegex(@"\bdiff\s*\(")]
    private static partial Regex Differentiation();
}
