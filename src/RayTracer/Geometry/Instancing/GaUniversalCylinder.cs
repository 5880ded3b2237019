using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Instancing;

/// <summary>
/// GAU-Cyl (thesis §7.2.1): an open tube in general position, the generic tube x² + z² = r²,
/// 0 ≤ y ≤ h, with its RSTR placement (base centre and unit axis) folded into the intersection
/// when the kernel is generated. What is left is the ray's height along the axis and its squared
/// distance from it; no ray is transformed. Seen from inside, the normal is turned towards the ray,
/// as on the other tubes.
/// </summary>
public sealed class GaUniversalCylinder : GeometricObject
{
    private readonly double _px, _py, _pz;
    private readonly double _vx, _vy, _vz;
    private readonly double _radius, _height;

    public GaUniversalCylinder(Point3D baseCentre, Vector3D axis, double radius)
    {
        if (!(radius > 0) || !double.IsFinite(radius))
            throw new ArgumentOutOfRangeException(nameof(radius), radius, "A cylinder needs a finite radius above 0.");
        if (!double.IsFinite(baseCentre.x) || !double.IsFinite(baseCentre.y) || !double.IsFinite(baseCentre.z))
            throw new ArgumentException($"A cylinder needs a finite base centre, not {baseCentre}.", nameof(baseCentre));
        var height = axis.Length;
        if (!(height > 0) || !double.IsFinite(height))
            throw new ArgumentException($"The axis of a cylinder must be a finite non-zero vector, not {axis}.", nameof(axis));
        (_px, _py, _pz) = (baseCentre.x, baseCentre.y, baseCentre.z);
        (_vx, _vy, _vz) = (axis.x / height, axis.y / height, axis.z / height);
        _radius = radius;
        _height = height;
    }

    public Point3D BaseCentre => new(_px, _py, _pz);

    /// <summary>The axis from the base centre to the top centre.</summary>
    public Vector3D Axis => new(_vx * _height, _vy * _height, _vz * _height);

    public double Radius => _radius;

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t, out _);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin, out var height))
            return false;

        var p = ray.At(tmin);
        var n = new Normal3D(
            (p.x - _px - height * _vx) / _radius,
            (p.y - _py - height * _vy) / _radius,
            (p.z - _pz - height * _vz) / _radius);
        if (n.x * ray.d.x + n.y * ray.d.y + n.z * ray.d.z > 0)
            n = -n;
        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = new TextureCoordinates(0, height / _height);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox()
    {
        var e = new Vector3D(
            _radius * Math.Sqrt(Math.Max(0, 1 - _vx * _vx)),
            _radius * Math.Sqrt(Math.Max(0, 1 - _vy * _vy)),
            _radius * Math.Sqrt(Math.Max(0, 1 - _vz * _vz)));
        var start = BaseCentre;
        var end = start + Axis;
        return new BoundingBox(Point3D.Min(start, end) - e, Point3D.Max(start, end) + e).Expanded(Tolerances.BoundsPadding);
    }

    // The nearest root past epsilon whose height lies on the tube; `height` is that height.
    private bool Solve(in Ray ray, out double t, out double height)
    {
        double a, hb, c, height0, rate;

        #region GMac : GauCylinderQuadratic
        //GMac.Bind("p.e1", "<_px>");
        //GMac.Bind("p.e2", "<_py>");
        //GMac.Bind("p.e3", "<_pz>");
        //GMac.Bind("v.e1", "<_vx>");
        //GMac.Bind("v.e2", "<_vy>");
        //GMac.Bind("v.e3", "<_vz>");
        //GMac.Bind("radius.1", "<_radius>");
        //GMac.Bind("o", "Point3D", ray.o);
        //GMac.Bind("d", "Vector3D", ray.d);
        //GMac.Bind("a.1", "<a>");
        //GMac.Bind("hb.1", "<hb>");
        //GMac.Bind("c.1", "<c>");
        //GMac.Bind("height0.1", "<height0>");
        //GMac.Bind("rate.1", "<rate>");
        double tmp0 = ray.o.x - _px;
        double tmp1 = ray.o.y - _py;
        double tmp2 = ray.o.z - _pz;
        double tmp3 = tmp0 * _vx + tmp1 * _vy + tmp2 * _vz;
        double tmp4 = ray.d.x * _vx + ray.d.y * _vy + ray.d.z * _vz;
        a = ray.d.x * ray.d.x + ray.d.y * ray.d.y + ray.d.z * ray.d.z - tmp4 * tmp4;
        hb = tmp0 * ray.d.x + tmp1 * ray.d.y + tmp2 * ray.d.z - tmp3 * tmp4;
        c = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2 - tmp3 * tmp3 - _radius * _radius;
        height0 = tmp3;
        rate = tmp4;
        #endregion

        var discriminant = hb * hb - a * c;
        if (a != 0 && discriminant >= 0)
        {
            // The root pair from q = −(hb ± √disc) without cancellation, nearer first.
            var q = -(hb + Math.CopySign(Math.Sqrt(discriminant), hb));
            var r0 = q / a;
            var r1 = q != 0 ? c / q : -r0;
            if (r0 > r1)
                (r0, r1) = (r1, r0);
            height = height0 + r0 * rate;
            if (r0 > ray.tMin && height >= 0 && height <= _height)
            {
                t = r0;
                return true;
            }

            height = height0 + r1 * rate;
            if (r1 > ray.tMin && height >= 0 && height <= _height)
            {
                t = r1;
                return true;
            }
        }

        t = 0;
        height = 0;
        return false;
    }
}
