using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>Rodrigues' formula about an axis through an origin by hand, four items per step (the scalar hand kernel's formula).</summary>
public sealed partial class RotateAboutAxisThroughPoint3DVectorKernel
{
    public override bool HasHand => true;

    protected override void Hand256(double[][] i, double[][] o)
    {
        var n = ItemsInSteps(i[0]);
        var one = Vector256.Create(1.0);
        for (var step = 0; step < n; step += 4)
        {
            var k = Math.Min(step, n - 4);
            var (ax, ay, az) = (Load(i[0], k), Load(i[1], k), Load(i[2], k));
            var (ox, oy, oz) = (Load(i[3], k), Load(i[4], k), Load(i[5], k));
            var (s, c) = Vector256.SinCos(Load(i[6], k));
            var inverseLength = one / Vector256.Sqrt(ax * ax + ay * ay + az * az);
            var (kx, ky, kz) = (ax * inverseLength, ay * inverseLength, az * inverseLength);
            var (ux, uy, uz) = (Load(i[7], k) - ox, Load(i[8], k) - oy, Load(i[9], k) - oz);
            var (cx, cy, cz) = (ky * uz - kz * uy, kz * ux - kx * uz, kx * uy - ky * ux);
            var f = (kx * ux + ky * uy + kz * uz) * (one - c);
            Store(ox + ux * c + cx * s + kx * f, o[0], k);
            Store(oy + uy * c + cy * s + ky * f, o[1], k);
            Store(oz + uz * c + cz * s + kz * f, o[2], k);
        }
    }
}
