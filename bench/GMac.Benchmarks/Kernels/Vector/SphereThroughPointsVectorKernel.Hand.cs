using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>The dual sphere through four points by hand (the scalar hand kernel's 4×4 minors), four items per step.</summary>
public sealed partial class SphereThroughPointsVectorKernel
{
    public override bool HasHand => true;

    protected override void Hand256(double[][] i, double[][] o)
    {
        var n = ItemsInSteps(i[0]);
        var half = Vector256.Create(0.5);
        for (var step = 0; step < n; step += 4)
        {
            var k = Math.Min(step, n - 4);
            var (x1, y1, z1) = (Load(i[0], k), Load(i[1], k), Load(i[2], k));
            var (x2, y2, z2) = (Load(i[3], k), Load(i[4], k), Load(i[5], k));
            var (x3, y3, z3) = (Load(i[6], k), Load(i[7], k), Load(i[8], k));
            var (x4, y4, z4) = (Load(i[9], k), Load(i[10], k), Load(i[11], k));
            var n1 = half * (x1 * x1 + y1 * y1 + z1 * z1);
            var (ax, ay, az, an) = (x2 - x1, y2 - y1, z2 - z1, half * (x2 * x2 + y2 * y2 + z2 * z2) - n1);
            var (bx, by, bz, bn) = (x3 - x1, y3 - y1, z3 - z1, half * (x3 * x3 + y3 * y3 + z3 * z3) - n1);
            var (cx, cy, cz, cn) = (x4 - x1, y4 - y1, z4 - z1, half * (x4 * x4 + y4 * y4 + z4 * z4) - n1);
            var (mxy, mxz, myz) = (bx * cy - by * cx, bx * cz - bz * cx, by * cz - bz * cy);
            var (mxn, myn, mzn) = (bx * cn - bn * cx, by * cn - bn * cy, bz * cn - bn * cz);
            var xyz = ax * myz - ay * mxz + az * mxy;
            var xyn = ax * myn - ay * mxn + an * mxy;
            var xzn = ax * mzn - az * mxn + an * mxz;
            var yzn = ay * mzn - az * myn + an * myz;
            Store(-xyz, o[0], k);
            Store(-yzn, o[1], k);
            Store(xzn, o[2], k);
            Store(-xyn, o[3], k);
            Store(n1 * xyz - x1 * yzn + y1 * xzn - z1 * xyn, o[4], k);
        }
    }
}
