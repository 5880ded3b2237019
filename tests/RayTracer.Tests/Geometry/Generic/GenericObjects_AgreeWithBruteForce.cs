using RayTracer.Geometry;
using RayTracer.Geometry.Generic;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Generic;

/// <summary>Each generic object against a marched implicit equation of the same surface.</summary>
public class GenericObjects_AgreeWithBruteForce
{
    private static double Phi(Point3D p)
    {
        double phi = Math.Atan2(p.x, p.z);
        return phi < 0 ? phi + 2 * Math.PI : phi;
    }

    public static TheoryData<string> Cases => ["open cylinder", "cone", "torus", "annulus", "part sphere", "part cylinder", "part torus"];

    private static (GeometricObject Obj, Func<Point3D, double> F, Func<Point3D, bool> Accept, bool Closed) Make(string name) => name switch
    {
        "open cylinder" => (new OpenCylinder(-1, 1.5, 1.2), p => p.x * p.x + p.z * p.z - 1.44, p => p.y >= -1 && p.y <= 1.5, false),
        "cone" => (new Cone(2, 1), p => p.x * p.x + p.z * p.z - 0.25 * (2 - p.y) * (2 - p.y), p => p.y >= 0 && p.y <= 2, false),
        "torus" => (new Torus(1.5, 0.5), Torus(1.5, 0.5), _ => true, true),
        "annulus" => (new Annulus(0.5, 1.8), p => p.y, p => Math.Sqrt(p.x * p.x + p.z * p.z) is >= 0.5 and <= 1.8, false),
        "part sphere" => (
            new PartSphere(1.7, 0.5, 4, 0.4, 2.2),
            p => p.x * p.x + p.y * p.y + p.z * p.z - 1.7 * 1.7,
            p => Phi(p) is >= 0.5 and <= 4 && Math.Acos(Math.Clamp(p.y / 1.7, -1, 1)) is >= 0.4 and <= 2.2,
            false),
        "part cylinder" => (new PartCylinder(-1, 1, 1.2, 1, 5), p => p.x * p.x + p.z * p.z - 1.44, p => p.y >= -1 && p.y <= 1 && Phi(p) is >= 1 and <= 5, false),
        _ => (new PartTorus(1.5, 0.5, 0, 3.5), Torus(1.5, 0.5), p => Phi(p) <= 3.5, false),
    };

    private static Func<Point3D, double> Torus(double a, double b) => p =>
    {
        double s = p.x * p.x + p.y * p.y + p.z * p.z + a * a - b * b;
        return s * s - 4 * a * a * (p.x * p.x + p.z * p.z);
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void Hits_match_marched_roots_and_normals_are_unit(string name)
    {
        var (obj, f, accept, closed) = Make(name);
        var random = new SeededRandom((ulong)name.GetHashCode(StringComparison.Ordinal) & 0xffff);
        var sr = new ShadingRecord();
        int hits = 0;
        for (int n = 0; n < 250; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, 6, 2);
            double? expected = ImplicitSurfaceMarch.FirstRoot(f, ray, 20, 1e-3, accept);
            bool hit = obj.Hit(ray, out double t, sr);
            Assert.True(expected.HasValue == hit, $"{name}: ray {ray} expected {expected}, got {(hit ? t : "miss")}");
            if (!hit)
            {
                continue;
            }

            hits++;
            Assert.Equal(expected!.Value, t, 6);
            Assert.Equal(1, sr.Normal.Length, 9);
            Assert.True(obj.Intersect(ray, out double t2) && t2 == t);
            if (closed)
            {
                // Outward: along the gradient of the implicit function.
                var p = ray.At(t);
                const double h = 1e-6;
                var grad = new Vector3D(
                    f(p + new Vector3D(h, 0, 0)) - f(p - new Vector3D(h, 0, 0)),
                    f(p + new Vector3D(0, h, 0)) - f(p - new Vector3D(0, h, 0)),
                    f(p + new Vector3D(0, 0, h)) - f(p - new Vector3D(0, 0, h)));
                Assert.True(sr.Normal.Dot(grad.Normalized()) > 0.999, $"{name}: normal {sr.Normal} vs gradient {grad.Normalized()}");
            }
            else if (name != "annulus")
            {
                Assert.True(sr.Normal.Dot(ray.d) <= 1e-12, $"{name}: open surfaces face the ray");
            }
        }

        Assert.True(hits > 20, $"{name}: only {hits} hits");
    }

    [Fact]
    public void Torus_along_the_equator_hits_the_outer_rim_and_through_the_hole_misses()
    {
        var torus = new Torus(2, 0.5);
        Assert.True(torus.Intersect(new Ray(new Point3D(-100, 0, 0), new Vector3D(1, 0, 0)), out double t));
        Assert.Equal(100 - 2.5, t, 9);
        Assert.False(torus.Intersect(new Ray(new Point3D(0, 50, 0), new Vector3D(0, -1, 0)), out _));
        // From inside the tube the first hit is the tube wall.
        Assert.True(torus.Intersect(new Ray(new Point3D(2, 0, 0), new Vector3D(0, 1, 0)), out t));
        Assert.Equal(0.5, t, 9);
    }

    [Fact]
    public void Grazing_the_cone_and_cylinder_rims()
    {
        var cylinder = new OpenCylinder(0, 1, 1);
        Assert.True(cylinder.Intersect(new Ray(new Point3D(-5, 0.5, 1 - 1e-7), new Vector3D(1, 0, 0)), out double t));
        Assert.Equal(5, t, 3);
        Assert.False(cylinder.Intersect(new Ray(new Point3D(-5, 0.5, 1 + 1e-7), new Vector3D(1, 0, 0)), out _));
        var cone = new Cone(1, 1);
        // Ray parallel to a generatrix: the quadratic degenerates to a linear equation.
        Assert.True(cone.Intersect(new Ray(new Point3D(-0.5, -1, 0), new Vector3D(1, 1, 0)), out t));
        var p = new Ray(new Point3D(-0.5, -1, 0), new Vector3D(1, 1, 0)).At(t);
        Assert.Equal(Math.Abs(p.x), 1 - p.y, 9);
    }
}
