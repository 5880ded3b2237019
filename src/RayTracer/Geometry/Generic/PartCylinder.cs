using RayTracer.Maths;

namespace RayTracer.Geometry.Generic;

/// <summary>Open cylinder restricted to an azimuth range [PhiMin, PhiMax] (radians, from +z towards +x).</summary>
public sealed class PartCylinder : OpenCylinder
{
    public PartCylinder(double bottom, double top, double radius, double phiMin, double phiMax)
        : base(bottom, top, radius)
    {
        Azimuth.CheckRange(phiMin, phiMax);
        PhiMin = phiMin;
        PhiMax = phiMax;
    }

    public double PhiMin { get; }

    public double PhiMax { get; }

    protected override bool Accept(Point3D p)
    {
        if (!base.Accept(p))
        {
            return false;
        }

        double phi = Azimuth.Of(p.x, p.z);
        return phi >= PhiMin && phi <= PhiMax;
    }
}
