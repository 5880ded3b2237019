namespace Twister.Tessellation;

/// <summary>
/// Adaptive polygonization of a parametric surface with complete edge sampling, after Velho, de
/// Figueiredo and Gomes, "A unified approach for hierarchical adaptive tesselation of surfaces"
/// (ACM TOG 18(4), 1999). The parameter square starts as a grid of square faces. A face stays whole
/// when each of its edges, probed as a curve at random points, and its interior, probed at the
/// centroids and random points of both diagonal cuts, lie within the tolerance; otherwise it is cut
/// in u, in v or both, across the direction that strays, and each part is tested the same way. Each
/// leaf is then triangulated from its complete boundary polygon, with no vertex inside: its corners
/// and every sample a finer neighbour placed on its edges.
/// A shared edge therefore carries the same samples for both faces beside it, and the mesh has no
/// cracks and no T-junctions. See <see cref="TriangleMesh"/> for the seams and poles of closed surfaces.
/// </summary>
public static class SurfaceTessellator
{
    public static TriangleMesh Tessellate(IParametricSurface surface, TessellationOptions options)
    {
        ArgumentNullException.ThrowIfNull(surface);
        ArgumentNullException.ThrowIfNull(options);
        options.Validate();
        return new SurfaceTessellation(surface, options).Run();
    }
}
