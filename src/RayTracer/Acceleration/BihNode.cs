namespace RayTracer.Acceleration;

/// <summary>
/// Bounding interval hierarchy node. Interior nodes (Axis 0..2) hold two clip planes: the largest
/// coordinate of the left child's objects and the smallest of the right child's; the children sit at
/// Child and Child + 1. Leaves (Axis 3) cover primitives [Child, Child + Count).
/// </summary>
internal struct BihNode
{
    public double LeftMax;
    public double RightMin;
    public int Child;
    public int Count;
    public int Axis;

    public const int LeafAxis = 3;
}
