using System.Runtime.Intrinsics;

namespace RayTracer.Kernels;

/// <summary>Eight 3D vectors or points, one per lane, in the x, y, z fields the class bindings read.</summary>
internal struct Vector3x8
{
    public Vector512<double> x;
    public Vector512<double> y;
    public Vector512<double> z;
}
