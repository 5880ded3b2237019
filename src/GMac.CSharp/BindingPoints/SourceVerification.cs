using System.Globalization;
using GMac.CSharp.Verification;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// The flow of <c>gmac verify</c>: generates every binding point under the paths, compiles the code
/// in its file and project, and compares each region with the numeric engine on random inputs.
/// </summary>
internal static class SourceVerification
{
    /// <summary>False when anything failed to generate, compile or agree.</summary>
    public static bool Run(GenerationContext context, IReadOnlyList<string> paths, int seed, TextWriter output, TextWriter error)
    {
        var (files, missing) = SourceScanner.Find(paths);
        foreach (var m in missing) error.WriteLine(m);
        var failures = missing.Count;
        var found = 0;
        var generations = new List<FileGeneration>();
        var regions = new List<(string Path, GeneratedRegion Region)>();
        foreach (var path in files)
        {
            var generation = SourceGeneration.GenerateFile(path, context, stats: false, error);
            if (generation is null)
            {
                failures++;
                continue;
            }
            found += generation.File.Points.Count;
            foreach (var d in generation.Diagnostics) error.WriteLine(d);
            failures += generation.Diagnostics.Count;
            var generated = generation.Regions.Where(r => r.Outcome is { Succeeded: true, Plan: not null } && r.Code is not null).ToList();
            if (generated.Count > 0) generations.Add(generation);
            regions.AddRange(generated.Select(r => (path, r)));
        }
        if (found == 0)
        {
            error.WriteLine($"gmac verify: no binding points found under {string.Join(", ", paths)}; nothing was verified");
            return false;
        }

        // The code must build where it is written, not only on its own.
        var notCompiling = new HashSet<GeneratedRegion>(ReferenceEqualityComparer.Instance);
        foreach (var failure in ProjectContextCompiler.Check(generations))
        {
            error.WriteLine(failure.Diagnostic);
            notCompiling.Add(failure.Region);
            failures++;
        }

        var remapped = regions.Select(r => KernelCompiler.Remap(r.Region.Outcome!.Result!.Block, r.Region.Outcome.Plan!.InputTexts.Keys, r.Region.Point.Scope.Storage)
            with { FusedMultiplyAdd = r.Region.FusedMultiplyAdd }).ToList();
        var kernels = KernelCompiler.Compile(remapped, regions.Select(r => r.Region.ScalarType).ToList());
        var passed = 0;
        for (var k = 0; k < regions.Count; k++)
        {
            var (path, region) = regions[k];
            var point = region.Point;
            var (kernel, compileError) = kernels[k];
            if (kernel is null)
            {
                error.WriteLine(new Diagnostic(DiagnosticCodes.KernelDoesNotCompile, SourceSpan.At(path, point.RegionLineNumber, point.RegionColumn), $"the code of '{point.MacroName}' does not compile: {compileError}"));
                failures++;
                continue;
            }
            var plan = region.Outcome!.Plan!;
            var tolerance = RegionVerifier.ToleranceFor(RegionVerifier.UsesDifferentiation(context.Project, plan.Macro), kernel.IsSingle);
            var assumptions = point.Specs.OfType<AssumptionSpec>().ToList();
            var normalized = NormalizedAtoms(context, point, plan);
            var result = RegionVerifier.Verify(kernel, plan, assumptions, normalized, tolerance, seed + k);
            if (!result.Passed)
            {
                error.WriteLine(new Diagnostic(DiagnosticCodes.DisagreesWithEngine, SourceSpan.At(path, point.RegionLineNumber, point.RegionColumn), $"'{point.MacroName}' disagrees with the numeric engine: {result.Failure}"));
                failures++;
                continue;
            }
            if (notCompiling.Contains(region)) continue;
            passed++;
            output.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"{path}({point.RegionLineNumber},{point.RegionColumn}): ok {point.MacroName}: {kernel.Outputs.Count} output(s), {result.Samples} samples, max relative error {result.MaxRelativeError:0.0e+00} (tolerance {result.Tolerance:0e+00})"));
        }
        output.WriteLine($"gmac verify: {regions.Count} region(s), {passed} passed, {failures} problem(s)");
        return failures == 0;
    }

    /// <summary>
    /// For each input of a normalized class, the atoms that feed it directly: random values are scaled
    /// so their squares sum to one, as the generated code may assume.
    /// </summary>
    private static IReadOnlyList<IReadOnlyList<string>> NormalizedAtoms(GenerationContext context, BindingPoint point, BindingPointPlan plan)
    {
        var groups = new List<IReadOnlyList<string>>();
        foreach (var input in plan.Macro.Inputs.Where(i => i.Class is { IsNormalized: true }))
        {
            var texts = new HashSet<string>(StringComparer.Ordinal);
            foreach (var spec in point.Specs)
            {
                switch (spec)
                {
                    case CoefficientBindingSpec c when c.Parameter == input.Name:
                        texts.Add(c.Value is TemplateValue { SingleHole: { } hole } ? hole.Text.Trim() : c.Value.Text.Trim());
                        break;
                    case ClassBindingSpec c when c.Parameter == input.Name:
                        foreach (var text in plan.InputTexts.Values.Where(v => v.StartsWith(c.Target.Trim() + ".", StringComparison.Ordinal))) texts.Add(text);
                        break;
                }
            }
            groups.Add(plan.InputTexts.Where(x => texts.Contains(x.Value.Trim())).Select(x => x.Key).ToList());
        }
        _ = context;
        return groups;
    }
}
