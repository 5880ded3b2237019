namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>The cross product u × v by hand, four items per step.</summary>
public sealed partial class NormalToVectorsVectorKernel
{
    public override bool HasHand => true;

    protected override void Hand256(double[][] i, double[][] o)
    {
        var n = ItemsInSteps(i[0]);
        for (var step = 0; step < n; step += 4)
        {
            var k = Math.Min(step, n - 4);
            var (ux, uy, uz) = (Load(i[0], k), Load(i[1], k), Load(i[2], k));
            var (vx, vy, vz) = (Load(i[3], k), Load(i[4], k), Load(i[5], k));
            Store(uy * vz - uz * vy, o[0], k);
            Store(uz * vx - ux * vz, o[1], k);
            Store(ux * vy - uy * vx, o[2], k);
        }
    }
}
