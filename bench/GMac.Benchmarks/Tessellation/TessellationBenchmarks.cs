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
            double theta = 2 * Math.PI * Turns * u, phi = 2 * Math.PI * v;
            double scale = Math.Exp(Growth * theta), ring = Radius + Tube * Math.Cos(phi);
            return new(scale * ring * Math.Cos(theta), scale * ring * Math.Sin(theta), scale * (Tube * Math.Sin(phi) - Drop));
        }

        /// <summary>∂S/∂u × ∂S/∂v from the closed-form partial derivatives.</summary>
        public TwistableVector NormalAt(double u, double v)
        {
            double theta = 2 * Math.PI * Turns * u, phi = 2 * Math.PI * v;
            double scale = Math.Exp(Growth * theta), ring = Radius + Tube * Math.Cos(phi);
            double cosT = Math.Cos(theta), sinT = Math.Sin(theta), cosP = Math.Cos(phi), sinP = Math.Sin(phi);
            double du = 2 * Math.PI * Turns * scale, dv = 2 * Math.PI * scale;

            // S = e^(kθ) F: ∂S/∂θ = e^(kθ) (k F + ∂F/∂θ), ∂S/∂φ = e^(kθ) ∂F/∂φ.
            double fx = ring * cosT, fy = ring * sinT, fz = Tube * sinP - Drop;
            double ux = du * (Growth * fx - ring * sinT), uy = du * (Growth * fy + ring * cosT), uz = du * Growth * fz;
            double vx = -dv * Tube * sinP * cosT, vy = -dv * Tube * sinP * sinT, vz = dv * Tube * cosP;
            return Cross(ux, uy, uz, vx, vy, vz);
        }
    }
}
