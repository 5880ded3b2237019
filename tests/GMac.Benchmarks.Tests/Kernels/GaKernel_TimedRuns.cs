using GMac.Benchmarks.Kernels;

namespace GMac.Benchmarks.Tests.Kernels;

public class GaKernel_TimedRuns
{
    [Fact]
    public void Timed_runs_of_every_variant_read_and_write_the_same_arrays()
    {
        var kernel = new RecordingKernel();
        kernel.Setup(16, seed: 3);
        foreach (var v in Enum.GetValues<Variant>()) kernel.Time(v);
        Assert.Equal(3, kernel.Calls.Count);
        Assert.Single(kernel.Calls.Select(c => c.Inputs).Distinct());
        Assert.Single(kernel.Calls.Select(c => c.Outputs).Distinct());
    }

    [Fact]
    public void Checked_runs_keep_each_variants_outputs_apart_from_the_timed_ones()
    {
        var kernel = new RecordingKernel();
        kernel.Setup(4, seed: 3);
        foreach (var v in Enum.GetValues<Variant>()) kernel.Run(v);
        kernel.Time(Variant.Hand);
        Assert.Equal(4, kernel.Calls.Select(c => c.Outputs).Distinct().Count());
        var input = (double)kernel.Input(0);
        Assert.Equal(input, kernel.Output(Variant.Generated, 0)[0]);
        Assert.Equal(input * 2, kernel.Output(Variant.Direct, 0)[0]);
        Assert.Equal(input * 3, kernel.Output(Variant.Hand, 0)[0]);
    }

    /// <summary>Each variant scales its input by its own factor and records the arrays it was given.</summary>
    private sealed class RecordingKernel : GaKernel<double, double>
    {
        public List<(double[] Inputs, double[] Outputs)> Calls { get; } = [];
        public override string MacroName => "Recording";
        public override string Source => "test";
        public override OperationCount HandOperations => new(0, 1, 0, 0);
        protected override double CreateInput(Random random) => random.NextDouble() + 1;
        protected override double[] Components(double value) => [value];
        protected override void RunGenerated(double[] inputs, double[] outputs) => Scale(inputs, outputs, 1);
        protected override void RunDirect(double[] inputs, double[] outputs) => Scale(inputs, outputs, 2);
        protected override void RunHand(double[] inputs, double[] outputs) => Scale(inputs, outputs, 3);

        private void Scale(double[] inputs, double[] outputs, double factor)
        {
            Calls.Add((inputs, outputs));
            for (var i = 0; i < inputs.Length; i++) outputs[i] = inputs[i] * factor;
        }
    }
}
