using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Textures;

namespace RayTracer.Geometry.Generic;

/// <summary>Disk of the given radius about the origin in the plane y = 0, normal +y.</summary>
public sealed class GenericDisk : GenericPlane
{
    public GenericDisk(double radius)
    {
        if (!(radius > 0))
        {
            throw new ArgumentOutOfRangeException(nameof(radius), radius, "A disk needs a positive radius.");
        }

        Radius = radius;
    }

    public double Radius { get; }

    public override BoundingBox GetBoundingBox() => new(-Radius, Radius, -Tolerances.BoundsPadding, Tolerances.BoundsPadding, -Radius, Radius);

    protected override bool Accept(double x, double z) => x * x + z * z < Radius * Radius;

    protected override TextureCoordinates Coordinates(double x, double z) =>
        new(Azimuth.Of(x, z) * MathConstants.InvTwoPi, Math.Sqrt(x * x + z * z) / Radius);
}
