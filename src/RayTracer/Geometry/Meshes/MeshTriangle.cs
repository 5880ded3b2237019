using System.Runtime.CompilerServices;
using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Kernels;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Triangle <see cref="Index"/> of a <see cref="Mesh"/>. Flat triangles use the face normal; smooth
/// ones interpolate the vertex normals with the barycentric coordinates of the hit. The test is the
/// mesh's <see cref="Mesh.TriangleTest"/> when the triangle is created, kept so that an acceleration
/// structure built over it and the triangle's own hit test always run the same arithmetic.
/// </summary>
public sealed class MeshTriangle : GeometricObject, ITriangle
{
    private readonly int _i0;
    private readonly int _i1;
    private readonly int _i2;

    public MeshTriangle(Mesh mesh, int index, bool smooth)
    {
        Mesh = mesh ?? throw new ArgumentNullException(nameof(mesh));
        if ((uint)index >= (uint)mesh.TriangleCount)
        {
            throw new ArgumentOutOfRangeException(nameof(index));
        }

        Index = index;
        Smooth = smooth;
        Test = mesh.TriangleTest;
        _i0 = mesh.Indices[3 * index];
        _i1 = mesh.Indices[3 * index + 1];
        _i2 = mesh.Indices[3 * index + 2];
        if (smooth && mesh.Normals is null)
        {
            throw new ArgumentException("Smooth triangles need vertex normals; call Mesh.ComputeVertexNormals first.");
        }
    }

    public Mesh Mesh { get; }

    public int Index { get; }

    public bool Smooth { get; }

    public Point3D V0 => Mesh.Vertices[_i0];

    public Point3D V1 => Mesh.Vertices[_i1];

    public Point3D V2 => Mesh.Vertices[_i2];

    public TriangleTest Test { get; }

    /// <summary>Falls back to the mesh's shared material.</summary>
    public override Material? Material
    {
        get => base.Material ?? Mesh.Material;
        set => base.Material = value;
    }

    public override bool Intersect(in Ray ray, out double t)
    {
        return Solve(ray, out t, out _, out _);
    }

    /// <summary>The mesh's test on this triangle: hit distance and the barycentrics of V1 (beta) and V2 (gamma).</summary>
    public bool Solve(in Ray ray, out double t, out double beta, out double gamma)
    {
        Point3D v0 = V0, v1 = V1, v2 = V2;
        return Test switch
        {
            TriangleTest.Algebraic => AlgebraicTriangleSolver.Intersect(ray, v0, v1 - v0, v2 - v0, double.PositiveInfinity, out t, out beta, out gamma),
            TriangleTest.Plucker => PluckerTriangleSolver.Intersect(ray, v0, v1, v2, double.PositiveInfinity, out t, out beta, out gamma),
            TriangleTest.PluckerEdges => PluckerTriangleSolver.Intersect(ray, PluckerTriangle.From(v0, v1, v2), double.PositiveInfinity, out t, out beta, out gamma),
            _ => TriangleSolver.Intersect(ray, v0, v1 - v0, v2 - v0, double.PositiveInfinity, out t, out beta, out gamma),
        };
    }

    /// <summary>False when either this triangle or its mesh is set not to cast shadows.</summary>
    public override bool CastsShadows
    {
        get => base.CastsShadows && Mesh.CastsShadows;
        set => base.CastsShadows = value;
    }

    public override bool ShadowHit(in Ray ray, out double tmin)
    {
        if (!CastsShadows)
        {
            tmin = 0;
            return false;
        }

        return Intersect(ray, out tmin);
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin, out double beta, out double gamma))
        {
            return false;
        }

        double alpha = 1 - beta - gamma;
        Normal3D n;
        if (Smooth)
        {
            var normals = Mesh.Normals!;
            n = alpha * normals[_i0] + beta * normals[_i1] + gamma * normals[_i2];
        }
        else
        {
            var v0 = V0;
            n = TriangleNormal.OfEdges(V1 - v0, V2 - v0);
        }

        sr.Normal = n.Normalized();
        sr.LocalHitPoint = ray.At(tmin);
        if (Mesh.TextureCoordinates is { } uvs)
        {
            TextureCoordinates a = uvs[_i0], b = uvs[_i1], c = uvs[_i2];
            sr.TextureCoordinates = new TextureCoordinates(
                alpha * a.u + beta * b.u + gamma * c.u, alpha * a.v + beta * b.v + gamma * c.v);
        }
        else
        {
            sr.TextureCoordinates = new TextureCoordinates(beta, gamma);
        }

        sr.Material = Material;
        return true;
    }

    /// <summary>Compiled optimized at once: a structure's build calls it for every triangle, often before tiered compilation would get to it.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public override BoundingBox GetBoundingBox()
    {
        Point3D v0 = V0, v1 = V1, v2 = V2;
        return new BoundingBox(Point3D.Min(v0, Point3D.Min(v1, v2)), Point3D.Max(v0, Point3D.Max(v1, v2)));
    }
}
