using System.Runtime.Intrinsics;

namespace RayTracer.Kernels;

/// <summary>Four 3D vectors or points, one per lane, in the x, y, z fields the class bindings read.</summary>
internal struct Vector3x4
{
    public Vector256<double> x;
    public Vector256<double> y;
    public Vector256<double> z;
}
