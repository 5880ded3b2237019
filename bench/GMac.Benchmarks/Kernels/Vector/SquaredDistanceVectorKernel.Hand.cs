namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>|u − v|² by hand, four items per step.</summary>
public sealed partial class SquaredDistanceVectorKernel
{
    public override bool HasHand => true;

    protected override void Hand256(double[][] i, double[][] o)
    {
        var n = ItemsInSteps(i[0]);
        for (var step = 0; step < n; step += 4)
        {
            var k = Math.Min(step, n - 4);
            var dx = Load(i[0], k) - Load(i[3], k);
            var dy = Load(i[1], k) - Load(i[4], k);
            var dz = Load(i[2], k) - Load(i[5], k);
            Store(dx * dx + dy * dy + dz * dz, o[0], k);
        }
    }
}
