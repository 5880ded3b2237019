using RayTracer.Geometry.Parametric;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Parametric;

public class TessellatedSurface_Hits
{
    private const double Tolerance = 1e-3;

    private static Vector3D RandomDirection(Random random)
    {
        while (true)
        {
            var d = new Vector3D(2 * random.NextDouble() - 1, 2 * random.NextDouble() - 1, 2 * random.NextDouble() - 1);
            if (d.LengthSquared is > 0.01 and <= 1)
            {
                return d.Normalized();
            }
        }
    }

    [Fact]
    public void Rays_at_a_sphere_hit_at_the_analytic_distance_with_the_analytic_normal_and_uv()
    {
        var surface = new TessellatedSurface(new ClosedForms.Sphere(1), Tolerance);
        var random = new Random(3);
        var sr = new ShadingRecord();
        for (var k = 0; k < 400; k++)
        {
            // Straight at the centre from distance 3: the sphere is 2 away, the inscribed mesh at most the tolerance farther.
            var outward = RandomDirection(random);
            var ray = new Ray(new Point3D(0, 0, 0) + 3 * outward, -outward);
            Assert.True(surface.Hit(ray, out var t, sr), $"ray {k} missed");
            Assert.InRange(t, 2 - 1e-9, 2 + Tolerance);
            Assert.True(Math.Acos(Math.Min(1, sr.Normal.Dot(outward))) < 0.01, $"normal {sr.Normal} vs {outward}");

            // u runs around the y axis from +z towards +x, v from the south pole up.
            var u = Math.Atan2(outward.x, outward.z) / (2 * Math.PI);
            u = u < 0 ? u + 1 : u;
            var v = Math.Acos(-outward.y) / Math.PI;
            var du = Math.Abs(sr.TextureCoordinates.u - u);
            if (Math.Abs(outward.y) < 0.95)
            {
                Assert.True(Math.Min(du, 1 - du) < 0.01, $"u {sr.TextureCoordinates.u} vs {u}");
            }

            Assert.True(Math.Abs(sr.TextureCoordinates.v - v) < 0.01, $"v {sr.TextureCoordinates.v} vs {v}");
        }
    }

    [Fact]
    public void Rays_at_a_torus_hit_where_the_analytic_torus_is_hit()
    {
        var surface = new TessellatedSurface(new ClosedForms.Torus(1, 0.4), Tolerance);
        var exact = new RayTracer.Geometry.Generic.Torus(1, 0.4);
        var random = new Random(5);
        var sr = new ShadingRecord();
        var compared = 0;
        for (var k = 0; k < 600; k++)
        {
            var target = new ClosedForms.Torus(1, 0.4).PointAt(random.NextDouble(), random.NextDouble());
            var origin = new Point3D(0, 0, 0) + 4 * RandomDirection(random);
            var ray = new Ray(origin, (new Point3D(target.x, target.y, target.z) - origin).Normalized());
            var onTorus = exact.Hit(ray, out var t, sr);
            var normal = sr.Normal;
            var cosine = onTorus ? Math.Abs(normal.Dot(ray.d)) : 0;
            if (cosine < 0.3)
            {
                continue; // misses and grazing hits: the mesh may rightly disagree there
            }

            compared++;
            Assert.True(surface.Hit(ray, out var tm, sr), $"ray {k} missed the mesh");
            Assert.True(Math.Abs(tm - t) <= Tolerance / cosine, $"ray {k}: mesh {tm}, torus {t}");
            Assert.True(Math.Acos(Math.Min(1, sr.Normal.Dot(normal))) < 0.02, $"normal {sr.Normal} vs {normal}");
        }

        Assert.True(compared > 100);
    }

    [Fact]
    public void The_mesh_carries_the_tessellation_with_normals_and_uv_and_takes_the_material()
    {
        var surface = new TessellatedSurface(new ClosedForms.Torus(1, 0.4), 1e-2);
        Assert.NotNull(surface.Mesh.Normals);
        Assert.NotNull(surface.Mesh.TextureCoordinates);
        Assert.Equal(surface.Mesh.TriangleCount, surface.PrimitiveCount);
        var material = RayTracer.Factories.MaterialFactory.Matte(RayTracer.Colors.RGBColor.White);
        surface.Material = material;
        var sr = new ShadingRecord();
        Assert.True(surface.Hit(new Ray(new Point3D(0, 3, 1), new Vector3D(0, -1, 0)), out _, sr));
        Assert.Same(material, sr.Material);
    }
}
