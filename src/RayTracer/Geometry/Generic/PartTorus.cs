using RayTracer.Maths;

namespace RayTracer.Geometry.Generic;

/// <summary>Torus restricted to an azimuth range about the y axis; open, so the normal faces the ray.</summary>
public sealed class PartTorus : Torus
{
    public PartTorus(double sweptRadius, double tubeRadius, double phiMin, double phiMax)
        : base(sweptRadius, tubeRadius)
    {
        Azimuth.CheckRange(phiMin, phiMax);
        PhiMin = phiMin;
        PhiMax = phiMax;
    }

    public double PhiMin { get; }

    public double PhiMax { get; }

    protected override bool FaceRay => true;

    protected override bool Accept(Point3D p)
    {
        double phi = Azimuth.Of(p.x, p.z);
        return phi >= PhiMin && phi <= PhiMax;
    }
}
