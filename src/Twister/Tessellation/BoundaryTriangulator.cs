namespace Twister.Tessellation;

/// <summary>
/// Triangulates a leaf cell from its boundary polygon alone: the corners of its parameter rectangle
/// and the samples that neighbours put on its sides. The polygon is convex, so every vertex where the
/// boundary turns is an ear unless its cut would run along a side (and leave the samples there
/// hanging); clipping ears gives n − 2 triangles for n vertices and no vertex inside,
/// and each cut joins two of the polygon's own vertices, so the shared edges stay exactly as sampled.
/// The ear with the shortest cut in space goes first, which lays a thin cell out as a zigzag strip
/// across its short way and cuts a plain rectangle along its shorter diagonal.
/// </summary>
internal static class BoundaryTriangulator
{
    /// <summary>Adds the triangles of <paramref name="polygon"/> (counter-clockwise in (u, v)); empties the list.</summary>
    public static void Triangulate(List<BoundaryVertex> polygon, MeshBuilder mesh)
    {
        long left = polygon.Min(v => v.I), right = polygon.Max(v => v.I), bottom = polygon.Min(v => v.J), top = polygon.Max(v => v.J);
        bool OnOneSide(BoundaryVertex p, BoundaryVertex r) =>
            (p.I == r.I && (p.I == left || p.I == right)) || (p.J == r.J && (p.J == bottom || p.J == top));
        while (polygon.Count > 3)
        {
            var best = -1;
            var shortest = double.PositiveInfinity;
            for (var k = 0; k < polygon.Count; k++)
            {
                var (p, q, r) = (polygon[(k + polygon.Count - 1) % polygon.Count], polygon[k], polygon[(k + 1) % polygon.Count]);
                if (!Turns(p, q, r) || OnOneSide(p, r))
                {
                    continue;
                }

                var cut = Geometry3.Distance(mesh.Position(p.Id), mesh.Position(r.Id));
                if (cut < shortest)
                {
                    (best, shortest) = (k, cut);
                }
            }

            var prev = polygon[(best + polygon.Count - 1) % polygon.Count];
            var next = polygon[(best + 1) % polygon.Count];
            mesh.AddTriangle(prev.Id, polygon[best].Id, next.Id);
            polygon.RemoveAt(best);
        }

        mesh.AddTriangle(polygon[0].Id, polygon[1].Id, polygon[2].Id);
        polygon.Clear();
    }

    /// <summary>
    /// All the vertices lie on the sides of an axis-aligned rectangle: three are in line only along one
    /// side.
    /// </summary>
    private static bool Turns(BoundaryVertex p, BoundaryVertex q, BoundaryVertex r) =>
        !(p.I == q.I && q.I == r.I) && !(p.J == q.J && q.J == r.J);
}
