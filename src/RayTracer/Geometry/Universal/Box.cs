using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>Solid axis-aligned box between two corners; normals are the outward face normals.</summary>
public sealed class Box : GeometricObject
{
    private readonly BoundingBox _bounds;

    public Box(Point3D p0, Point3D p1)
    {
        _bounds = new BoundingBox(Point3D.Min(p0, p1), Point3D.Max(p0, p1));
        var d = _bounds.Diagonal;
        if (!(d.x > 0 && d.y > 0 && d.z > 0))
        {
            throw new ArgumentException("A box needs a positive extent along every axis.");
        }
    }

    public Point3D Min => _bounds.Min;

    public Point3D Max => _bounds.Max;

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t, out _);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin, out int face))
        {
            return false;
        }

        sr.Normal = FaceNormal(face);
        sr.LocalHitPoint = ray.At(tmin);
        sr.TextureCoordinates = default;
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => _bounds;

    /// <summary>Faces 0..2 are the -x, -y, -z sides, 3..5 the +x, +y, +z sides.</summary>
    private static Normal3D FaceNormal(int face) => face switch
    {
        0 => new Normal3D(-1, 0, 0),
        1 => new Normal3D(0, -1, 0),
        2 => new Normal3D(0, 0, -1),
        3 => new Normal3D(1, 0, 0),
        4 => new Normal3D(0, 1, 0),
        _ => new Normal3D(0, 0, 1),
    };

    private bool Solve(in Ray ray, out double t, out int face)
    {
        double tIn = double.NegativeInfinity, tOut = double.PositiveInfinity;
        int faceIn = -1, faceOut = -1;
        for (int axis = 0; axis < 3; axis++)
        {
            double o = ray.o[axis], d = ray.d[axis];
            double lo = _bounds.Min[axis], hi = _bounds.Max[axis];
            if (d == 0)
            {
                // Parallel to this slab: inside it or never.
                if (o < lo || o > hi)
                {
                    t = 0;
                    face = -1;
                    return false;
                }

                continue;
            }

            double inv = 1.0 / d;
            double t0 = (lo - o) * inv, t1 = (hi - o) * inv;
            int f0 = axis, f1 = axis + 3;
            if (t0 > t1)
            {
                (t0, t1) = (t1, t0);
                (f0, f1) = (f1, f0);
            }

            if (t0 > tIn)
            {
                tIn = t0;
                faceIn = f0;
            }

            if (t1 < tOut)
            {
                tOut = t1;
                faceOut = f1;
            }
        }

        if (tIn < tOut && tOut > ray.tMin)
        {
            if (tIn > ray.tMin)
            {
                t = tIn;
                face = faceIn;
            }
            else
            {
                t = tOut;
                face = faceOut;
            }

            return true;
        }

        t = 0;
        face = -1;
        return false;
    }
}
