using RayTracer.Bounds;

namespace RayTracer.Acceleration;

/// <summary>
/// Node of the binary SAH tree. An interior node (Count = 0) has its two children at Offset and
/// Offset + 1, allocated together so that subtrees can be built in parallel; a leaf (Count &gt; 0)
/// covers primitives [Offset, Offset + Count) of the build order.
/// </summary>
internal struct BvhNode
{
    public BoundingBox Bounds;
    public int Offset;
    public int Count;
}
