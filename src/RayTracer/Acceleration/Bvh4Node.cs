using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace RayTracer.Acceleration;

/// <summary>
/// Four-wide BVH node: the boxes of up to four children in structure-of-arrays form, so one set of
/// vector operations tests all four against a ray. The boxes are the builder's single-precision boxes
/// (rounded outward from the primitives' double boxes), so storing them as floats loses nothing; a
/// node is 128 bytes, two cache lines when the array is aligned (<see cref="Bvh"/> aligns it), where
/// double-precision boxes took 216 bytes over four lines. The six planes are consecutive, x, y, z of the
/// minimum corner then of the maximum, so a traversal can pick a ray's near and far planes by index.
/// A child reference is a node index when non-negative and the complement (~i) of a leaf index
/// otherwise; unused slots are masked out by <see cref="ValidMask"/>.
/// </summary>
[StructLayout(LayoutKind.Sequential, Size = 128)]
internal struct Bvh4Node
{
    public Vector128<float> MinX;
    public Vector128<float> MinY;
    public Vector128<float> MinZ;
    public Vector128<float> MaxX;
    public Vector128<float> MaxY;
    public Vector128<float> MaxZ;
    public int Child0;
    public int Child1;
    public int Child2;
    public int Child3;
    public int ValidMask;
}
