using Twister.Tessellation;
using Twister.Tests.Tessellation.Shapes;
using Xunit.Abstractions;

namespace Twister.Tests.Tessellation;

public class SurfaceTessellator_Adaptivity(ITestOutputHelper output)
{
    [Theory]
    [InlineData("bump", 1e-3)]
    [InlineData("torus", 1e-3)]
    [InlineData("sphere", 1e-3)]
    public void At_equal_measured_error_the_adaptive_mesh_needs_fewer_triangles_than_a_uniform_grid(string name, double tolerance)
    {
        var surface = SurfaceTessellator_Accuracy.ByName(name);
        var adaptive = SurfaceTessellator.Tessellate(surface, new TessellationOptions(tolerance));
        var error = MeshMeasure.MaxChordError(surface, adaptive);
        var cells = MeshMeasure.UniformCellsFor(surface, error);
        var uniform = 2 * cells * cells;
        output.WriteLine(FormattableString.Invariant(
            $"{name}: tolerance {tolerance}, measured error {error:G3}, adaptive {adaptive.TriangleCount} triangles, uniform {cells}×{cells} = {uniform}, ratio {(double)adaptive.TriangleCount / uniform:F3}"));
        Assert.True(adaptive.TriangleCount < uniform, $"adaptive {adaptive.TriangleCount} vs uniform {uniform}");
    }
}
