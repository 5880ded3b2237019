using System.Runtime.Intrinsics;

namespace RayTracer.Acceleration;

/// <summary>
/// Four-wide BVH node: the boxes of up to four children in structure-of-arrays form, so one set of
/// vector operations tests all four against a ray. A child reference is a node index when
/// non-negative and the complement (~i) of a leaf index otherwise; unused slots are masked out by
/// <see cref="ValidMask"/>.
/// </summary>
internal struct Bvh4Node
{
    public Vector256<double> MinX;
    public Vector256<double> MinY;
    public Vector256<double> MinZ;
    public Vector256<double> MaxX;
    public Vector256<double> MaxY;
    public Vector256<double> MaxZ;
    public int Child0;
    public int Child1;
    public int Child2;
    public int Child3;
    public int ValidMask;
}
