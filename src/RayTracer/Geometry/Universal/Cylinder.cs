using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>
/// Circular cylinder in general position, defined by its base center, its axis vector (direction and
/// height) and its radius. The ray is split into components along and across the axis, which
/// reduces the test to a 2D circle in the plane perpendicular to the axis. Optionally capped.
/// </summary>
public sealed class Cylinder : GeometricObject
{
    private readonly Vector3D _unitAxis;
    private readonly double _height;

    public Cylinder(Point3D baseCenter, Vector3D axis, double radius, bool capped = false)
    {
        if (!(radius > 0) || axis.LengthSquared == 0)
        {
            throw new ArgumentException("A cylinder needs a positive radius and a non-zero axis.");
        }

        BaseCenter = baseCenter;
        Axis = axis;
        Radius = radius;
        Capped = capped;
        _height = axis.Length;
        _unitAxis = axis / _height;
    }

    public Point3D BaseCenter { get; }

    public Vector3D Axis { get; }

    public double Radius { get; }

    public bool Capped { get; }

    /// <summary>
    /// For uncapped cylinders seen from inside, turn the normal towards the viewer (there is no outside
    /// to speak of). Compounds that use the tube as part of a closed solid set this to false.
    /// </summary>
    public bool NormalFacesRay { get; set; } = true;

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t, out _);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin, out int part))
        {
            return false;
        }

        var p = ray.At(tmin);
        var rel = p - BaseCenter;
        double h = Vector3D.Dot(rel, _unitAxis);
        Normal3D n;
        if (part == 0)
        {
            n = new Normal3D((rel - h * _unitAxis).Normalized());
            if (!Capped && NormalFacesRay && n.Dot(ray.d) > 0)
            {
                n = -n;
            }
        }
        else
        {
            n = new Normal3D(part == 1 ? -_unitAxis : _unitAxis);
        }

        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = new TextureCoordinates(0, h / _height);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox()
    {
        var top = BaseCenter + Axis;
        var e = new Vector3D(
            Radius * Math.Sqrt(Math.Max(0, 1 - _unitAxis.x * _unitAxis.x)),
            Radius * Math.Sqrt(Math.Max(0, 1 - _unitAxis.y * _unitAxis.y)),
            Radius * Math.Sqrt(Math.Max(0, 1 - _unitAxis.z * _unitAxis.z)));
        return new BoundingBox(Point3D.Min(BaseCenter, top) - e, Point3D.Max(BaseCenter, top) + e).Expanded(Tolerances.BoundsPadding);
    }

    /// <summary>part: 0 tube, 1 base cap, 2 top cap.</summary>
    private bool Solve(in Ray ray, out double t, out int part)
    {
        var oc = ray.o - BaseCenter;
        double dAxial = Vector3D.Dot(ray.d, _unitAxis);
        double oAxial = Vector3D.Dot(oc, _unitAxis);
        var dPerp = ray.d - dAxial * _unitAxis;
        var oPerp = oc - oAxial * _unitAxis;

        t = double.PositiveInfinity;
        part = -1;
        Span<double> roots = stackalloc double[2];
        int n = PolynomialSolver.SolveQuadratic(
            oPerp.LengthSquared - Radius * Radius, 2 * Vector3D.Dot(oPerp, dPerp), dPerp.LengthSquared, roots);
        for (int i = 0; i < n; i++)
        {
            double h = oAxial + roots[i] * dAxial;
            if (roots[i] > ray.tMin && h >= 0 && h <= _height)
            {
                t = roots[i];
                part = 0;
                break;
            }
        }

        if (Capped && dAxial != 0)
        {
            for (int cap = 1; cap <= 2; cap++)
            {
                double tc = ((cap == 1 ? 0 : _height) - oAxial) / dAxial;
                if (tc > ray.tMin && tc < t && (oPerp + tc * dPerp).LengthSquared <= Radius * Radius)
                {
                    t = tc;
                    part = cap;
                }
            }
        }

        if (part < 0)
        {
            t = 0;
            return false;
        }

        return true;
    }
}
