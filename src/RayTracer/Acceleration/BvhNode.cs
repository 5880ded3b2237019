using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace RayTracer.Acceleration;

/// <summary>
/// Node of the binary SAH tree. An interior node (Count = 0) has its two children at Offset and
/// Offset + 1, allocated together so that subtrees can be built in parallel; a leaf (Count &gt; 0)
/// covers primitives [Offset, Offset + Count) of the build order. The box is the builder's, in single
/// precision (x, y, z and a zero lane), converted exactly when the four-wide nodes are filled.
/// </summary>
internal struct BvhNode
{
    public Vector128<float> Min;
    public Vector128<float> Max;
    public int Offset;
    public int Count;

    /// <summary>The box's surface area, computed in double as <see cref="Bounds.BoundingBox.SurfaceArea"/> would.</summary>
    public readonly double SurfaceArea
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get
        {
            double dx = (double)Max.GetElement(0) - Min.GetElement(0);
            double dy = (double)Max.GetElement(1) - Min.GetElement(1);
            double dz = (double)Max.GetElement(2) - Min.GetElement(2);
            return 2.0 * (dx * dy + dy * dz + dz * dx);
        }
    }
}
