using RayTracer.Maths;
using RayTracer.Bounds;
using RayTracer.Textures;

namespace RayTracer.Geometry.Generic;

/// <summary>Rectangle |x| ≤ HalfWidth, |z| ≤ HalfDepth in the plane y = 0, normal +y.</summary>
public sealed class GenericRectangle : GenericPlane
{
    public GenericRectangle(double halfWidth, double halfDepth)
    {
        if (!(halfWidth > 0) || !(halfDepth > 0))
        {
            throw new ArgumentException("A rectangle needs positive half sizes.");
        }

        HalfWidth = halfWidth;
        HalfDepth = halfDepth;
    }

    public double HalfWidth { get; }

    public double HalfDepth { get; }

    public override BoundingBox GetBoundingBox() => new(-HalfWidth, HalfWidth, -Tolerances.BoundsPadding, Tolerances.BoundsPadding, -HalfDepth, HalfDepth);

    protected override bool Accept(double x, double z) => Math.Abs(x) <= HalfWidth && Math.Abs(z) <= HalfDepth;

    protected override TextureCoordinates Coordinates(double x, double z) =>
        new(0.5 * (x / HalfWidth + 1), 0.5 * (z / HalfDepth + 1));
}
