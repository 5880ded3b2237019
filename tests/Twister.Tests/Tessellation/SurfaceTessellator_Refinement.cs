using Twister.Tessellation;
using Twister.Tests.Tessellation.Shapes;

namespace Twister.Tests.Tessellation;

public class SurfaceTessellator_Refinement
{
    private static readonly double[] StartingLines = [0, 0.25, 0.5, 0.75, 1];

    [Fact]
    public void A_surface_curved_in_one_direction_is_refined_only_in_that_direction()
    {
        // Waves along u only: every iso-curve in v is a straight line, so no cell needs splitting in v
        // and every vertex stays on a line of the starting grid.
        var ridges = new HeightSheet(
            (x, y) => 0.1 * Math.Sin(2 * Math.PI * x),
            (x, y) => 0.2 * Math.PI * Math.Cos(2 * Math.PI * x),
            (x, y) => 0);
        var mesh = SurfaceTessellator.Tessellate(ridges, new TessellationOptions(1e-4));
        Assert.All(mesh.Parameters, p => Assert.Contains(p.V, StartingLines));
        Assert.True(mesh.Parameters.Select(p => p.U).Distinct().Count() > 20);
        Assert.InRange(MeshMeasure.MaxChordError(ridges, mesh), 0, 1e-4);

        // Strips of long thin cells need no vertex inside a cell: two triangles per cell.
        var columns = mesh.Parameters.Select(p => p.U).Distinct().Count() - 1;
        Assert.Equal(2 * columns * (StartingLines.Length - 1), mesh.TriangleCount);
    }

    [Fact]
    public void A_change_to_the_surface_in_one_part_leaves_the_samples_elsewhere_unchanged()
    {
        // The two sheets agree for u ≥ 0.5; probes belong to their edge or cell, not to the order in
        // which the cells were visited, so the last column of starting cells samples the same points.
        static double Waves(double x, double y) => 0.1 * Math.Sin(2 * Math.PI * x) * Math.Sin(2 * Math.PI * y);
        static double Bump(double x, double y) => 0.2 * Math.Exp(-((x - 0.2) * (x - 0.2) + (y - 0.5) * (y - 0.5)) / 0.005);
        var plain = new HeightSheet(Waves, (x, y) => 0, (x, y) => 0);
        var bumped = new HeightSheet((x, y) => Waves(x, y) + Bump(x, y), (x, y) => 0, (x, y) => 0);
        var options = new TessellationOptions(1e-3);
        static SurfaceParameter[] Right(TriangleMesh mesh) =>
            [.. mesh.Parameters.Where(p => p.U > 0.75).OrderBy(p => p.U).ThenBy(p => p.V)];
        var left = Right(SurfaceTessellator.Tessellate(plain, options));
        Assert.True(left.Length > 50);
        Assert.Equal(left, Right(SurfaceTessellator.Tessellate(bumped, options)));
    }
}
