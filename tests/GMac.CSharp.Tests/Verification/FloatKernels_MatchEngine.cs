using System.Text.RegularExpressions;
using GMac.CSharp.Tests.Support;
using GMac.CSharp.Verification;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// Float code of library macros compiles, uses only float arithmetic, and agrees with the numeric
/// engine (run on doubles) to float accuracy; a float kernel that is off still fails.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed partial class FloatKernels_MatchEngine
{
    [Theory]
    [InlineData("NormalToVectors")]
    [InlineData("SphereThroughPoints")]
    [InlineData("RotationVersor")]
    [InlineData("RotorToMatrix")]
    [InlineData("SkewLinesClosestPoints")]
    [InlineData("ApplyUnitRotor3D")]
    [InlineData("ApplyVersorToPoint")]
    [InlineData("SphereCentreAndRadius")]
    [InlineData("PgaMotorExp")]
    [InlineData("PgaMotorLog")]
    [InlineData("CgaMotorLog")]
    [InlineData("PgaMotorSqrt")]
    public void Float_code_of_a_library_macro_matches_the_double_engine_to_float_accuracy(string macro)
    {
        var kernel = MacroKernel.Create(macro, "float");
        Assert.True(kernel.Kernel.IsSingle);
        Assert.DoesNotContain("double", kernel.Code);
        Assert.DoesNotMatch(@"\bMath\.", kernel.Code);
        Assert.Empty(DoubleLiteral().Matches(kernel.Code));
        var normalized = kernel.Plan.Macro.Inputs.Where(i => i.Class is { IsNormalized: true })
            .Select(i => (IReadOnlyList<string>)kernel.Plan.InputTexts.Where(x => x.Value.StartsWith(i.Name + "_", StringComparison.Ordinal)).Select(x => x.Key).ToList())
            .ToList();
        var result = RegionVerifier.Verify(kernel.Kernel, kernel.Plan, [], normalized, RegionVerifier.SingleTolerance, seed: 7, samples: 20);
        Assert.True(result.Passed, result.Failure);
        Assert.True(result.Samples >= 10, $"only {result.Samples} samples");
    }

    [Fact]
    public void A_float_kernel_off_by_a_thousandth_fails_at_float_tolerance()
    {
        var kernel = MacroKernel.Create("NormalToVectors", "float").Kernel;
        var wrong = kernel with
        {
            Run = (input, output) =>
            {
                kernel.Run(input, output);
                output[0] *= 1 + 1e-3;
            },
        };
        var plan = MacroKernel.Create("NormalToVectors", "float").Plan;
        Assert.False(RegionVerifier.Verify(wrong, plan, [], [], RegionVerifier.SingleTolerance, seed: 3).Passed);
    }

    [Fact]
    public void Float_kernels_really_compute_in_float()
    {
        // Same inputs, double and float code of one macro: the float results carry float rounding.
        var single = MacroKernel.Create("SphereThroughPoints", "float");
        var exact = MacroKernel.Create("SphereThroughPoints", "double");
        var random = new Random(5);
        var inputs = single.InputNames.ToDictionary(n => n, _ => (double)(float)(random.NextDouble() * 2 - 1));
        var a = single.Run(inputs);
        var b = exact.Run(inputs);
        Assert.Contains(a.Keys, k => a[k] != b[k]);
        Assert.All(a.Keys, k => Assert.Equal(b[k], a[k], 1e-4));
        Assert.All(a.Values, v => Assert.Equal(v, (float)v));
    }

    /// <summary>A decimal literal without the f suffix.</summary>
    [GeneratedRegex(@"\b\d+\.\d+(E[-+]?\d+)?(?![\dfE])")]
    private static partial Regex DoubleLiteral();
}
