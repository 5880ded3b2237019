using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Generic;

/// <summary>
/// Piece of the sphere of given radius about the origin with azimuth in [PhiMin, PhiMax] (from +z
/// towards +x) and polar angle in [ThetaMin, ThetaMax] (from +y). Open surface: the normal faces the ray.
/// </summary>
public sealed class PartSphere : GeometricObject
{
    public PartSphere(double radius, double phiMin, double phiMax, double thetaMin, double thetaMax)
    {
        if (!(radius > 0))
        {
            throw new ArgumentOutOfRangeException(nameof(radius), radius, "A sphere needs a positive radius.");
        }

        Azimuth.CheckRange(phiMin, phiMax);
        if (!(thetaMin >= 0 && thetaMax <= Math.PI + Tolerances.RelativeRounding && thetaMin < thetaMax))
        {
            throw new ArgumentException($"Polar range [{thetaMin}, {thetaMax}] must satisfy 0 ≤ min < max ≤ π.");
        }

        Radius = radius;
        PhiMin = phiMin;
        PhiMax = phiMax;
        ThetaMin = thetaMin;
        ThetaMax = thetaMax;
    }

    public double Radius { get; }

    public double PhiMin { get; }

    public double PhiMax { get; }

    public double ThetaMin { get; }

    public double ThetaMax { get; }

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        var n = new Normal3D(p.x, p.y, p.z).Normalized();
        var uv = new TextureCoordinates(
            Azimuth.Of(p.x, p.z) * MathConstants.InvTwoPi, 1 - Math.Acos(Math.Clamp(n.y, -1, 1)) * MathConstants.InvPi);
        if (n.Dot(ray.d) > 0)
        {
            n = -n;
        }

        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = uv;
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => new(-Radius, Radius, -Radius, Radius, -Radius, Radius);

    private bool Solve(in Ray ray, out double t)
    {
        if (SphereSolver.Intersect(ray, Point3D.Origin, Radius, out double t0, out double t1))
        {
            if (t0 > ray.tMin && Accept(ray.At(t0)))
            {
                t = t0;
                return true;
            }

            if (t1 > ray.tMin && Accept(ray.At(t1)))
            {
                t = t1;
                return true;
            }
        }

        t = 0;
        return false;
    }

    private bool Accept(Point3D p)
    {
        double phi = Azimuth.Of(p.x, p.z);
        double theta = Math.Acos(Math.Clamp(p.y / Radius, -1, 1));
        return phi >= PhiMin && phi <= PhiMax && theta >= ThetaMin && theta <= ThetaMax;
    }
}
