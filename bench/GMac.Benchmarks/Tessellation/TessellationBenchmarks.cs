using BenchmarkDotNet.Attributes;
using Twister;
using Twister.Tessellation;

namespace GMac.Benchmarks.Tessellation;

/// <summary>
/// Adaptive tessellation of the catalogue's torus and seashell (<see cref="TwistSurfaces"/>, evaluated
/// through their twist cascades) to a tolerance of one thousandth of the shape's size (the diagonal of
/// its bounding box), on one thread. The triangle count is printed by the setup.
/// </summary>
public class TessellationBenchmarks
{
    private IParametricSurface _surface = null!;
    private TessellationOptions _options = null!;

    [Params("torus", "seashell")]
    public string Shape { get; set; } = "";

    [GlobalSetup]
    public void Setup()
    {
        // Seashell: three whorls, each 0.8 above the last (the tube's diameter), shrinking by e^−0.5 in all.
        _surface = Shape == "torus"
            ? TwistSurfaces.Torus(1, 0.4)
            : TwistSurfaces.Seashell(1, 0.4, 3, 2.4, -0.5);
        _options = new TessellationOptions(1e-3 * Size(_surface));
        var mesh = SurfaceTessellator.Tessellate(_surface, _options);
        Console.WriteLine(FormattableString.Invariant(
            $"// {Shape}: tolerance {_options.Tolerance:G3}, {mesh.TriangleCount} triangles, {mesh.VertexCount} vertices"));
    }

    [Benchmark]
    public int Tessellate() => SurfaceTessellator.Tessellate(_surface, _options).TriangleCount;

    /// <summary>Diagonal of the bounding box of a dense grid of surface points.</summary>
    private static double Size(IParametricSurface surface)
    {
        double[] min = [double.MaxValue, double.MaxValue, double.MaxValue], max = [double.MinValue, double.MinValue, double.MinValue];
        for (var i = 0; i <= 256; i++)
        {
            for (var j = 0; j <= 256; j++)
            {
                var p = surface.PointAt(i / 256.0, j / 256.0);
                double[] c = [p.x, p.y, p.z];
                for (var k = 0; k < 3; k++)
                {
                    min[k] = Math.Min(min[k], c[k]);
                    max[k] = Math.Max(max[k], c[k]);
                }
            }
        }

        return Math.Sqrt(Enumerable.Range(0, 3).Sum(k => (max[k] - min[k]) * (max[k] - min[k])));
    }
}
