using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Universal;

public class Sphere_Hits
{
    private static readonly Sphere Unit = new(new Point3D(1, 2, 3), 2);

    [Fact]
    public void HeadOnRayHitsAtDistanceMinusRadius()
    {
        var sr = new ShadingRecord(null);
        Assert.True(Unit.Hit(new Ray(new Point3D(1, 2, 13), new Vector3D(0, 0, -1)), out double t, sr));
        Assert.Equal(8, t, 12);
        Assert.Equal(new Normal3D(0, 0, 1), sr.Normal);
    }

    [Fact]
    public void RayFromInsideHitsTheFarSideWithOutwardNormal()
    {
        var sr = new ShadingRecord(null);
        Assert.True(Unit.Hit(new Ray(new Point3D(1, 2, 3), new Vector3D(0, 2, 0)), out double t, sr));
        Assert.Equal(1, t, 12); // direction length 2, radius 2
        Assert.Equal(1, sr.Normal.y, 12);
    }

    [Fact]
    public void GrazingRaysHitJustInsideAndMissJustOutside()
    {
        var origin = new Point3D(1, 2 + 2 - 1e-6, -10);
        Assert.True(Unit.Intersect(new Ray(origin, new Vector3D(0, 0, 1)), out double t));
        Assert.Equal(13, t, 2);
        Assert.False(Unit.Intersect(new Ray(new Point3D(1, 2 + 2 + 1e-6, -10), new Vector3D(0, 0, 1)), out _));
    }

    [Fact]
    public void SphereBehindTheRayIsMissed()
    {
        Assert.False(Unit.Intersect(new Ray(new Point3D(1, 2, 10), new Vector3D(0, 0, 1)), out _));
    }

    [Fact]
    public void RandomHitsLieOnTheSurfaceWithUnitOutwardNormals()
    {
        var random = new SeededRandom(51);
        var sr = new ShadingRecord(null);
        int hits = 0;
        for (int n = 0; n < 2000; n++)
        {
            Ray ray = ImplicitSurfaceMarch.RandomRayTowards(random, 8, 3);
            ray.o = ray.o + new Vector3D(1, 2, 3);
            if (!Unit.Hit(ray, out double t, sr))
            {
                continue;
            }

            hits++;
            Point3D p = ray.At(t);
            Assert.Equal(2, p.Distance(Unit.Center), 9);
            Assert.Equal(1, sr.Normal.Length, 12);
            Assert.True(sr.Normal.Dot(p - Unit.Center) > 0);
            Assert.InRange(sr.TextureCoordinates.u, 0, 1);
            Assert.InRange(sr.TextureCoordinates.v, 0, 1);
        }

        Assert.True(hits > 500);
    }

    [Fact]
    public void SamplesLieOnTheSurfaceAndPdfIsOneOverArea()
    {
        var random = new SeededRandom(52);
        Vector3D mean = Vector3D.Zero;
        for (int n = 0; n < 20_000; n++)
        {
            Point3D p = Unit.Sample(new Point2D(random.NextDouble(), random.NextDouble()));
            Assert.Equal(2, p.Distance(Unit.Center), 12);
            mean += (p - Unit.Center) / 20_000;
        }

        // Uniform samples average to the centre (standard error about 0.008 per axis).
        Assert.True(mean.Length < 0.06, $"mean offset {mean}");
        Assert.Equal(1 / (16 * Math.PI), Unit.Pdf(new ShadingRecord(null)), 15);
    }
}
