using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>
/// Solid box in any position and orientation: a centre, an orthonormal frame and half extents along
/// its axes. The slab test runs in the box's own frame, where it is axis-aligned.
/// </summary>
public sealed class OrientedBox : GeometricObject
{
    private readonly Vector3D[] _axes;
    private readonly double[] _half;

    /// <summary>
    /// <paramref name="axisU"/> and <paramref name="axisV"/> give the orientation (V is made
    /// perpendicular to U; the third axis is U × V); half extents are along U, V and U × V.
    /// </summary>
    public OrientedBox(Point3D center, Vector3D axisU, Vector3D axisV, Vector3D halfExtents)
    {
        var u = axisU.Normalized();
        var v = axisV - Vector3D.Dot(axisV, u) * u;
        if (!(v.LengthSquared > 0) || !double.IsFinite(u.x))
        {
            throw new ArgumentException("The box axes must be non-zero and not parallel.");
        }

        if (!(halfExtents.x > 0 && halfExtents.y > 0 && halfExtents.z > 0))
        {
            throw new ArgumentException("A box needs positive half extents.", nameof(halfExtents));
        }

        v.Normalize();
        Center = center;
        _axes = [u, v, Vector3D.Cross(u, v)];
        _half = [halfExtents.x, halfExtents.y, halfExtents.z];
    }

    public Point3D Center { get; }

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t, out _);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin, out var n))
        {
            return false;
        }

        sr.Normal = n;
        sr.LocalHitPoint = ray.At(tmin);
        sr.TextureCoordinates = default;
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox()
    {
        // Half width along world axis i is Σ_k |axis_k[i]| · half_k.
        var e = new Vector3D(Extent(0), Extent(1), Extent(2));
        return new BoundingBox(Center - e, Center + e);
    }

    private double Extent(int i) =>
        Math.Abs(_axes[0][i]) * _half[0] + Math.Abs(_axes[1][i]) * _half[1] + Math.Abs(_axes[2][i]) * _half[2];

    private bool Solve(in Ray ray, out double t, out Normal3D normal)
    {
        var rel = ray.o - Center;
        double tIn = double.NegativeInfinity, tOut = double.PositiveInfinity;
        int axisIn = -1, axisOut = -1;
        double signIn = 0, signOut = 0;
        for (int k = 0; k < 3; k++)
        {
            double o = Vector3D.Dot(rel, _axes[k]), d = Vector3D.Dot(ray.d, _axes[k]);
            if (d == 0)
            {
                if (Math.Abs(o) > _half[k])
                {
                    t = 0;
                    normal = default;
                    return false;
                }

                continue;
            }

            double t0 = (-_half[k] - o) / d, t1 = (_half[k] - o) / d;
            double s0 = -1, s1 = 1;
            if (t0 > t1)
            {
                (t0, t1) = (t1, t0);
                (s0, s1) = (s1, s0);
            }

            if (t0 > tIn)
            {
                tIn = t0;
                axisIn = k;
                signIn = s0;
            }

            if (t1 < tOut)
            {
                tOut = t1;
                axisOut = k;
                signOut = s1;
            }
        }

        if (tIn < tOut && tOut > ray.tMin)
        {
            bool entering = tIn > ray.tMin;
            t = entering ? tIn : tOut;
            int axis = entering ? axisIn : axisOut;
            normal = new Normal3D((entering ? signIn : signOut) * _axes[axis]);
            return true;
        }

        t = 0;
        normal = default;
        return false;
    }
}
