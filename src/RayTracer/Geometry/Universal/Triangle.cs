using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Kernels;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>Stand-alone flat triangle; normal along (v1 − v0) × (v2 − v0), from the generated <see cref="TriangleNormal"/> kernel.</summary>
public sealed class Triangle : GeometricObject, ITriangle, ISampledShape
{
    private readonly Vector3D _e1;
    private readonly Vector3D _e2;

    public Triangle(Point3D v0, Point3D v1, Point3D v2)
    {
        V0 = v0;
        V1 = v1;
        V2 = v2;
        _e1 = v1 - v0;
        _e2 = v2 - v0;
        var n = TriangleNormal.OfEdges(_e1, _e2);
        Area = 0.5 * n.Length;
        Normal = Area > 0 ? n.Normalized() : default;
    }

    public Point3D V0 { get; }

    public Point3D V1 { get; }

    public Point3D V2 { get; }

    public Normal3D Normal { get; }

    public double Area { get; }

    public override bool Intersect(in Ray ray, out double t) =>
        TriangleSolver.Intersect(ray, V0, _e1, _e2, double.PositiveInfinity, out t, out _, out _);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!TriangleSolver.Intersect(ray, V0, _e1, _e2, double.PositiveInfinity, out tmin, out double beta, out double gamma))
        {
            return false;
        }

        sr.Normal = Normal;
        sr.LocalHitPoint = ray.At(tmin);
        sr.TextureCoordinates = new TextureCoordinates(beta, gamma);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox()
    {
        var box = BoundingBox.Empty;
        box.Include(V0);
        box.Include(V1);
        box.Include(V2);
        return box;
    }

    /// <summary>Uniform over the area (square-root warp of the unit square).</summary>
    public Point3D Sample(Point2D u)
    {
        double s = Math.Sqrt(u.x);
        return V0 + (s * (1 - u.y)) * _e1 + (s * u.y) * _e2;
    }

    public double Pdf(ShadingRecord sr) => 1.0 / Area;

    public Normal3D GetNormal(Point3D p) => Normal;
}
