using RayTracer.Bounds;

namespace RayTracer.Acceleration;

/// <summary>
/// Flattened BVH node in depth-first order: an interior node's first child follows it directly and
/// <see cref="Offset"/> is the second child; a leaf (Count &gt; 0) covers primitives [Offset, Offset + Count).
/// </summary>
internal struct BvhNode
{
    public BoundingBox Bounds;
    public int Offset;
    public int Count;
    public int Axis;
}
