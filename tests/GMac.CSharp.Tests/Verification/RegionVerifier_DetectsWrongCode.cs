using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.CSharp.Verification;
using GMac.Dsl.Generation;

namespace GMac.CSharp.Tests.Verification;

/// <summary>The verifier is not a rubber stamp: code that differs from the macro fails, code that compiles badly is reported.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class RegionVerifier_DetectsWrongCode
{
    private static GenerationOutcome NormalOutcome()
    {
        var context = SharedDsl.Context;
        var outcome = context.Generator.Generate("NormalToVectors", context.Generator.DefaultBindings("NormalToVectors"), 1);
        Assert.True(outcome.Succeeded);
        return outcome;
    }

    [Fact]
    public void Generated_kernel_passes_and_a_perturbed_one_fails()
    {
        var outcome = NormalOutcome();
        var remapped = KernelCompiler.Remap(outcome.Result!.Block, outcome.Plan!.InputTexts.Keys);
        var kernel = KernelCompiler.Compile([remapped])[0].Kernel!;
        var good = RegionVerifier.Verify(kernel, outcome.Plan, [], [], RegionVerifier.Tolerance, seed: 3);
        Assert.True(good.Passed, good.Failure);

        var wrong = kernel with
        {
            Run = (input, output) =>
            {
                kernel.Run(input, output);
                output[1] *= 1 + 1e-6;
            },
        };
        var bad = RegionVerifier.Verify(wrong, outcome.Plan, [], [], RegionVerifier.Tolerance, seed: 3);
        Assert.False(bad.Passed);
        Assert.Contains($"output '{kernel.Outputs[1]}'", bad.Failure);
    }

    /// <summary>A vector kernel is checked lane by lane: one wrong lane fails, and the failure names it.</summary>
    [Fact]
    public void A_vector_kernel_with_one_wrong_lane_fails()
    {
        var outcome = NormalOutcome();
        var remapped = KernelCompiler.Remap(outcome.Result!.Block, outcome.Plan!.InputTexts.Keys);
        var kernel = KernelCompiler.Compile([remapped], ["Vector256<double>"])[0].Kernel!;
        Assert.Equal(4, kernel.Lanes);
        var good = RegionVerifier.Verify(kernel, outcome.Plan, [], [], RegionVerifier.Tolerance, seed: 3);
        Assert.True(good.Passed, good.Failure);
        Assert.Equal(8, good.Samples);

        var wrong = kernel with
        {
            Run = (input, output) =>
            {
                kernel.Run(input, output);
                output[1 * kernel.Lanes + 2] *= 1 + 1e-6;
            },
        };
        var bad = RegionVerifier.Verify(wrong, outcome.Plan, [], [], RegionVerifier.Tolerance, seed: 3);
        Assert.False(bad.Passed);
        Assert.Contains($"output '{kernel.Outputs[1]}'", bad.Failure);
        Assert.Contains("lane 2", bad.Failure);
    }

    /// <summary>
    /// The kernel writes an in-place output over its input's slot, as the file's code does: code that
    /// writes it before the input's last read (as if the two names did not alias) fails.
    /// </summary>
    [Fact]
    public void In_place_code_that_overwrites_an_input_too_early_fails()
    {
        var context = SharedDsl.Context;
        BindingSpec[] specs = [new ClassBindingSpec("u", "Vector3D", "ψ", 1, 1), new ClassBindingSpec("v", "Vector3D", "b", 2, 1), new ClassBindingSpec("w", "Vector3D", "this.ψ", 3, 1)];
        var outcome = context.Generator.Generate("NormalToVectors", specs, 1);
        Assert.True(outcome.Succeeded);
        var remapped = KernelCompiler.Remap(outcome.Result!.Block, outcome.Plan!.InputTexts.Keys);
        Assert.Equal(3, remapped.InPlace.Count);

        var kernel = KernelCompiler.Compile([remapped])[0].Kernel!;
        var good = RegionVerifier.Verify(kernel, outcome.Plan, [], [], RegionVerifier.Tolerance, seed: 3);
        Assert.True(good.Passed, good.Failure);

        var unheld = KernelCompiler.Compile([remapped with { MayOverwrite = (_, _) => false }])[0].Kernel!;
        Assert.False(RegionVerifier.Verify(unheld, outcome.Plan, [], [], RegionVerifier.Tolerance, seed: 3).Passed);
    }

    [Fact]
    public void Swapped_outputs_fail()
    {
        var outcome = NormalOutcome();
        var remapped = KernelCompiler.Remap(outcome.Result!.Block, outcome.Plan!.InputTexts.Keys);
        var kernel = KernelCompiler.Compile([remapped])[0].Kernel!;
        var swapped = kernel with { Outputs = kernel.Outputs.Reverse().ToList() };
        Assert.False(RegionVerifier.Verify(swapped, outcome.Plan, [], [], RegionVerifier.Tolerance, seed: 5).Passed);
    }

    [Fact]
    public void Assumption_bounds_limit_the_sampled_inputs()
    {
        var context = SharedDsl.Context;
        BindingSpec[] specs =
        [
            new CoefficientBindingSpec("angle", "1", new HostExpression("cr", HasEffects: false), 1, 1),
            new CoefficientBindingSpec("x", "e1", new HostExpression("px", HasEffects: false), 2, 1),
            new CoefficientBindingSpec("x", "e2", new HostExpression("py", HasEffects: false), 3, 1),
            new CoefficientBindingSpec("y", "e1", new HostExpression("qx", HasEffects: false), 4, 1),
            new CoefficientBindingSpec("y", "e2", new HostExpression("qy", HasEffects: false), 5, 1),
            new AssumptionSpec("cr", new Core.Numerics.Rational(2, 1), true, 6, 1),
            new AssumptionSpec("cr", new Core.Numerics.Rational(3, 1), false, 7, 1),
        ];
        var outcome = context.Generator.Generate("Rotate2D", specs, 1);
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var inputs = outcome.Plan!.InputTexts.Keys.ToList();
        var angleSlot = inputs.FindIndex(n => outcome.Plan.InputTexts[n] == "cr");
        var seen = new List<double>();
        var kernel = new CompiledKernel((input, output) =>
        {
            seen.Add(input[angleSlot]);
            Array.Fill(output, 0);
        }, inputs, outcome.Result!.Block.OutputTargets.Keys.Order(StringComparer.Ordinal).ToList());
        RegionVerifier.Verify(kernel, outcome.Plan, specs.OfType<AssumptionSpec>().ToList(), [], 1e300, seed: 1);
        Assert.Equal(5, seen.Count);
        Assert.All(seen, v => Assert.InRange(v, 2.0, 3.0));
    }
}
