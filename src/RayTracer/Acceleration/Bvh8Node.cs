using System.Runtime.Intrinsics;

namespace RayTracer.Acceleration;

/// <summary>
/// Eight-wide BVH node, used where <see cref="Vector512"/> is accelerated: the boxes of up to eight
/// children in structure-of-arrays form, tested against a ray with one set of <see cref="Vector512{T}"/>
/// operations. Child references and <see cref="ValidMask"/> as in <see cref="Bvh4Node"/>.
/// </summary>
internal struct Bvh8Node
{
    public Vector512<double> MinX;
    public Vector512<double> MinY;
    public Vector512<double> MinZ;
    public Vector512<double> MaxX;
    public Vector512<double> MaxY;
    public Vector512<double> MaxZ;
    public int Child0;
    public int Child1;
    public int Child2;
    public int Child3;
    public int Child4;
    public int Child5;
    public int Child6;
    public int Child7;
    public int ValidMask;
}
