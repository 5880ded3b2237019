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
/// ones interpolate the vertex normals with the barycentric coordinates of the hit.
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

    /// <summary>Falls back to the mesh's shared material.</summary>
    public override Material? Material
    {
        get => base.Material ?? Mesh.Material;
        set => base.Material = value;
    }

    public override bool Intersect(in Ray ray, out double t)
    {
        var v0 = V0;
        return TriangleSolver.Intersect(ray, v0, V1 - v0, V2 - v0, double.PositiveInfinity, out t, out _, out _);
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
        var v0 = V0;
        Vector3D e1 = V1 - v0, e2 = V2 - v0;
        if (!TriangleSolver.Intersect(ray, v0, e1, e2, double.PositiveInfinity, out tmin, out double beta, out double gamma))
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
            n = TriangleNormal.OfEdges(e1, e2);
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

    public override BoundingBox GetBoundingBox()
    {
        var box = BoundingBox.Empty;
        box.Include(V0);
        box.Include(V1);
        box.Include(V2);
        return box;
    }
}
