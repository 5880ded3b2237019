using RayTracer.Geometry.Meshes;
using RayTracer.Materials;
using Twister;
using Twister.Tessellation;

namespace RayTracer.Geometry.Parametric;

/// <summary>
/// A parametric surface rendered through its adaptive tessellation (thesis §6.3.3): smooth-shaded
/// triangles with the surface's own normals and (u, v) as texture coordinates, in one hierarchy.
/// </summary>
public sealed class TessellatedSurface : AcceleratedGroup
{
    /// <param name="tolerance">Largest distance between the surface and its triangles, in scene units.</param>
    public TessellatedSurface(IParametricSurface surface, double tolerance)
        : this(surface, new TessellationOptions(tolerance))
    {
    }

    public TessellatedSurface(IParametricSurface surface, TessellationOptions options)
    {
        ArgumentNullException.ThrowIfNull(surface);
        Mesh = TwisterMeshes.ToMesh(SurfaceTessellator.Tessellate(surface, options));
        Build(Mesh.CreateTriangles(smooth: true));
    }

    public Mesh Mesh { get; }

    /// <summary>The material is the mesh's, shared by all its triangles.</summary>
    public override Material? Material
    {
        get => Mesh.Material;
        set => Mesh.Material = value;
    }
}
