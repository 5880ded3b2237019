using BenchmarkDotNet.Attributes;
using Twister;
using Twister.Tessellation;

namespace GMac.Benchmarks.Tessellation;

/// <summary>
/// Adaptive tessellation of a torus and of a seashell (a logarithmic-spiral tube) to a tolerance of
/// one thousandth of the shape's size, on one thread. The shapes are closed forms, so the timing is
/// the tessellator's own; the triangle count is printed by the setup.
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
        _surface = Shape == "torus" ? new Torus() : new Seashell();
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

    private static TwistableVector Cross(double ax, double ay, double az, double bx, double by, double bz) =>
        new(ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx);

    /// <summary>Torus about the z axis, radii 1 and 0.4.</summary>
    private sealed class Torus : IParametricSurface
    {
        private const double Swept = 1, Tube = 0.4;

        public TwistablePoint PointAt(double u, double v)
        {
            double a = 2 * Math.PI * u, b = 2 * Math.PI * v, ring = Swept + Tube * Math.Cos(b);
            return new(ring * Math.Cos(a), ring * Math.Sin(a), Tube * Math.Sin(b));
        }

        public TwistableVector NormalAt(double u, double v)
        {
            double a = 2 * Math.PI * u, b = 2 * Math.PI * v, ring = Swept + Tube * Math.Cos(b);
            var k = 4 * Math.PI * Math.PI * Tube * ring;
            return new(k * Math.Cos(b) * Math.Cos(a), k * Math.Cos(b) * Math.Sin(a), k * Math.Sin(b));
        }
    }

    /// <summary>
    /// A torus-like tube wound three times round the z axis while it grows and sinks by the factor
    /// e^(kθ): S = e^(kθ) ((R + r cos φ) cos θ, (R + r cos φ) sin θ, r sin φ − H), θ = 6πu, φ = 2πv.
    /// </summary>
    private sealed class Seashell : IParametricSurface
    {
        private const double Turns = 3, Growth = 0.12, Radius = 1, Tube = 0.45, Drop = 1.2;

        public TwistablePoint PointAt(double u, double v)
        {
            var (f, _, _) = Parts(u, v);
            return new(f[0], f[1], f[2]);
        }

        /// <summary>∂S/∂u × ∂S/∂v from the closed-form partial derivatives.</summary>
        public TwistableVector NormalAt(double u, double v)
        {
            var (_, su, sv) = Parts(u, v);
            return Cross(su[0], su[1], su[2], sv[0], sv[1], sv[2]);
        }

        private static (double[] S, double[] Su, double[] Sv) Parts(double u, double v)
        {
            double theta = 2 * Math.PI * Turns * u, phi = 2 * Math.PI * v;
            double scale = Math.Exp(Growth * theta), ring = Radius + Tube * Math.Cos(phi);
            double[] f = [ring * Math.Cos(theta), ring * Math.Sin(theta), Tube * Math.Sin(phi) - Drop];
            double[] fTheta = [-ring * Math.Sin(theta), ring * Math.Cos(theta), 0];
            double[] fPhi = [-Tube * Math.Sin(phi) * Math.Cos(theta), -Tube * Math.Sin(phi) * Math.Sin(theta), Tube * Math.Cos(phi)];
            double dTheta = 2 * Math.PI * Turns, dPhi = 2 * Math.PI;
            var s = f.Select(x => scale * x).ToArray();
            var su = Enumerable.Range(0, 3).Select(k => dTheta * scale * (Growth * f[k] + fTheta[k])).ToArray();
            var sv = fPhi.Select(x => dPhi * scale * x).ToArray();
            return (s, su, sv);
        }
    }
}
