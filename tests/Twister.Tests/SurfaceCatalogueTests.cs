using Twister;

namespace Twister.Tests;

/// <summary>Every catalogue surface against its equation; normals against ∂S/∂u × ∂S/∂v of that equation.</summary>
public sealed class SurfaceCatalogueTests
{
    private const double Tau = 2 * Math.PI;

    /// <summary>A catalogue surface with its closed form S(u, v) and the partials ∂S/∂u, ∂S/∂v.</summary>
    public sealed record Case(string Name, IParametricSurface Surface, Func<double, double, TwistablePoint> Point,
        Func<double, double, TwistableVector> ByU, Func<double, double, TwistableVector> ByV)
    {
        public override string ToString() => Name;
    }

    private static TwistableVector V(double x, double y, double z) => new(x, y, z);

    public static TheoryData<Case> Cases()
    {
        var data = new TheoryData<Case>();
        // (6.11) with c = (1, −2, 0.5), r = 2.
        data.Add(new("sphere", TwistSurfaces.Sphere(new(1, -2, 0.5), 2),
            (u, v) => new(1 + 2 * Math.Sin(Math.PI * u) * Math.Sin(Tau * v), -2 - 2 * Math.Sin(Math.PI * u) * Math.Cos(Tau * v), 0.5 + 2 * Math.Cos(Math.PI * u)),
            (u, v) => V(2 * Math.PI * Math.Cos(Math.PI * u) * Math.Sin(Tau * v), -2 * Math.PI * Math.Cos(Math.PI * u) * Math.Cos(Tau * v), -2 * Math.PI * Math.Sin(Math.PI * u)),
            (u, v) => V(2 * Tau * Math.Sin(Math.PI * u) * Math.Cos(Tau * v), 2 * Tau * Math.Sin(Math.PI * u) * Math.Sin(Tau * v), 0)));
        // Figure 6-1 first: r = 1.5, h = 2, k = 3; angle 2π(k u − v).
        data.Add(new("helix cylinder", TwistSurfaces.HelixCylinder(1.5, 2, 3),
            (u, v) => new(1.5 * Math.Cos(Tau * (3 * u - v)), 1.5 * Math.Sin(Tau * (3 * u - v)), 2 * u),
            (u, v) => V(-1.5 * 3 * Tau * Math.Sin(Tau * (3 * u - v)), 1.5 * 3 * Tau * Math.Cos(Tau * (3 * u - v)), 2),
            (u, v) => V(1.5 * Tau * Math.Sin(Tau * (3 * u - v)), -1.5 * Tau * Math.Cos(Tau * (3 * u - v)), 0)));
        data.Add(new("circle cylinder", TwistSurfaces.CircleCylinder(1.5, 2),
            (u, v) => new(1.5 * Math.Cos(Tau * u), 1.5 * Math.Sin(Tau * u), 2 * v),
            (u, v) => V(-1.5 * Tau * Math.Sin(Tau * u), 1.5 * Tau * Math.Cos(Tau * u), 0),
            (u, v) => V(0, 0, 2)));
        data.Add(new("cone", TwistSurfaces.Cone(1.2, 3),
            (u, v) => new((1 - v) * 1.2 * Math.Cos(Tau * u), (1 - v) * 1.2 * Math.Sin(Tau * u), 3 * v),
            (u, v) => V(-(1 - v) * 1.2 * Tau * Math.Sin(Tau * u), (1 - v) * 1.2 * Tau * Math.Cos(Tau * u), 0),
            (u, v) => V(-1.2 * Math.Cos(Tau * u), -1.2 * Math.Sin(Tau * u), 3)));
        data.Add(new("torus", TwistSurfaces.Torus(2, 0.5),
            (u, v) => new((2 + 0.5 * Math.Cos(Tau * u)) * Math.Cos(Tau * v), (2 + 0.5 * Math.Cos(Tau * u)) * Math.Sin(Tau * v), -0.5 * Math.Sin(Tau * u)),
            (u, v) => V(-0.5 * Tau * Math.Sin(Tau * u) * Math.Cos(Tau * v), -0.5 * Tau * Math.Sin(Tau * u) * Math.Sin(Tau * v), -0.5 * Tau * Math.Cos(Tau * u)),
            (u, v) => V(-Tau * (2 + 0.5 * Math.Cos(Tau * u)) * Math.Sin(Tau * v), Tau * (2 + 0.5 * Math.Cos(Tau * u)) * Math.Cos(Tau * v), 0)));
        data.Add(new("helicoid", TwistSurfaces.Helicoid(1, 2, 1.5),
            (u, v) => new((2 * u - 1) * Math.Cos(1.5 * Tau * v), (2 * u - 1) * Math.Sin(1.5 * Tau * v), 2 * v),
            (u, v) => V(2 * Math.Cos(1.5 * Tau * v), 2 * Math.Sin(1.5 * Tau * v), 0),
            (u, v) => V(-(2 * u - 1) * 1.5 * Tau * Math.Sin(1.5 * Tau * v), (2 * u - 1) * 1.5 * Tau * Math.Cos(1.5 * Tau * v), 2)));
        // The circle (2, 0, 0) + 0.5 (cos 2πu, sin 2πu, 0) turned about the y axis by −2πv.
        data.Add(new("revolution of a circle", TwistSurfaces.Revolution(TwistCurves.Circle(new(2, 0, 0), 0.5), new(0, 1, 0), default),
            (u, v) => new((2 + 0.5 * Math.Cos(Tau * u)) * Math.Cos(Tau * v), 0.5 * Math.Sin(Tau * u), (2 + 0.5 * Math.Cos(Tau * u)) * Math.Sin(Tau * v)),
            (u, v) => V(-0.5 * Tau * Math.Sin(Tau * u) * Math.Cos(Tau * v), 0.5 * Tau * Math.Cos(Tau * u), -0.5 * Tau * Math.Sin(Tau * u) * Math.Sin(Tau * v)),
            (u, v) => V(-Tau * (2 + 0.5 * Math.Cos(Tau * u)) * Math.Sin(Tau * v), 0, Tau * (2 + 0.5 * Math.Cos(Tau * u)) * Math.Cos(Tau * v))));
        data.Add(Column());
        data.Add(Shell());
        return data;
    }

    /// <summary>Epitrochoid E(u) = 1.2 (cos 2πu, sin 2πu) − 0.1 (cos 12πu, sin 12πu) turned by πv about z and lifted by 3v.</summary>
    private static Case Column()
    {
        var section = TwistCurves.Epitrochoid(1, 0.2, 0.1, 1);
        static (double X, double Y, double Dx, double Dy) E(double u) => (
            1.2 * Math.Cos(Tau * u) - 0.1 * Math.Cos(6 * Tau * u), 1.2 * Math.Sin(Tau * u) - 0.1 * Math.Sin(6 * Tau * u),
            Tau * (-1.2 * Math.Sin(Tau * u) + 0.6 * Math.Sin(6 * Tau * u)), Tau * (1.2 * Math.Cos(Tau * u) - 0.6 * Math.Cos(6 * Tau * u)));
        static (double, double) Rotate(double x, double y, double a) => (x * Math.Cos(a) - y * Math.Sin(a), x * Math.Sin(a) + y * Math.Cos(a));
        return new("twisted column", TwistSurfaces.TwistedColumn(section, 3, Math.PI),
            (u, v) => { var e = E(u); var (x, y) = Rotate(e.X, e.Y, Math.PI * v); return new(x, y, 3 * v); },
            (u, v) => { var e = E(u); var (x, y) = Rotate(e.Dx, e.Dy, Math.PI * v); return V(x, y, 0); },
            (u, v) => { var e = E(u); var (x, y) = Rotate(e.X, e.Y, Math.PI * v); return V(-Math.PI * y, Math.PI * x, 3); });
    }

    /// <summary>e^(g v) (Rz(2πkv) (R + r cos 2πu, 0, −r sin 2πu) + (0, 0, h v)), R = 1, r = 0.4, k = 3, h = 0.5, g = −0.5.</summary>
    private static Case Shell()
    {
        const double R = 1, r = 0.4, k = 3, h = 0.5, g = -0.5;
        static TwistablePoint S(double u, double v)
        {
            var rho = R + r * Math.Cos(Tau * u);
            var s = Math.Exp(g * v);
            return new(s * rho * Math.Cos(Tau * k * v), s * rho * Math.Sin(Tau * k * v), s * (-r * Math.Sin(Tau * u) + h * v));
        }
        return new("seashell", TwistSurfaces.Seashell(R, r, k, h, g), S,
            (u, v) =>
            {
                var s = Math.Exp(g * v);
                var d = -r * Tau * Math.Sin(Tau * u);
                return V(s * d * Math.Cos(Tau * k * v), s * d * Math.Sin(Tau * k * v), -s * r * Tau * Math.Cos(Tau * u));
            },
            (u, v) =>
            {
                var p = S(u, v);
                var s = Math.Exp(g * v);
                return V(g * p.x - Tau * k * p.y, g * p.y + Tau * k * p.x, g * p.z + s * h);
            });
    }

    private static (double U, double V)[] RandomParameters(int seed)
    {
        var random = new Random(seed);
        return [.. Enumerable.Range(0, 25).Select(_ => (random.NextDouble(), random.NextDouble()))];
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Points_equal_the_closed_form(Case c)
    {
        foreach (var (u, v) in RandomParameters(11))
            Near.Equal(c.Point(u, v), c.Surface.PointAt(u, v), 1e-12, $"{c.Name} at ({u}, {v})");
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Normals_equal_the_cross_product_of_the_closed_form_partials(Case c)
    {
        foreach (var (u, v) in RandomParameters(12))
            Near.Equal(Near.Cross(c.ByU(u, v), c.ByV(u, v)), c.Surface.NormalAt(u, v), 1e-12, $"{c.Name} normal at ({u}, {v})");
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Normals_equal_the_cross_product_of_central_differences(Case c)
    {
        foreach (var (u, v) in RandomParameters(13))
        {
            var su = Near.Difference(x => c.Surface.PointAt(x, v), u);
            var sv = Near.Difference(y => c.Surface.PointAt(u, y), v);
            Near.Equal(Near.Cross(su, sv), c.Surface.NormalAt(u, v), 1e-6, $"{c.Name} normal at ({u}, {v})");
        }
    }

    [Fact]
    public void Sphere_normals_point_away_from_the_centre()
    {
        var centre = new TwistablePoint(1, -2, 0.5);
        var sphere = TwistSurfaces.Sphere(centre, 2);
        foreach (var (u, v) in RandomParameters(14))
        {
            var p = sphere.PointAt(u, v);
            var n = sphere.NormalAt(u, v);
            var outward = new TwistableVector(p.x - centre.x, p.y - centre.y, p.z - centre.z);
            Assert.True(Near.Dot(n, outward) > 0, $"normal {n} at {p} points inward");
        }
    }

    [Fact]
    public void Torus_normals_point_away_from_the_tube_centre()
    {
        var torus = TwistSurfaces.Torus(2, 0.5);
        foreach (var (u, v) in RandomParameters(15))
        {
            var p = torus.PointAt(u, v);
            var n = torus.NormalAt(u, v);
            var ring = Math.Sqrt(p.x * p.x + p.y * p.y);
            var tube = new TwistableVector(p.x - 2 * p.x / ring, p.y - 2 * p.y / ring, p.z);
            Assert.True(Near.Dot(n, tube) > 0, $"normal {n} at {p} points into the tube");
        }
    }
}
