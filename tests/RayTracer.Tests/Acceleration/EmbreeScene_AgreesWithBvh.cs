using RayTracer.Acceleration;
using RayTracer.Acceleration.Embree;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

/// <summary>Where Embree is installed, it and our BVH see the same small mesh alike; skipped elsewhere.</summary>
public class EmbreeScene_AgreesWithBvh
{
    [EmbreeFact]
    public void Primary_rays_hit_alike_at_the_same_distances()
    {
        var mesh = ThroughputReport.DisplacedSphere(2000);
        var bvh = new Bvh(mesh.CreateTriangles(smooth: false));
        using var embree = EmbreeScene.TryCreate(mesh, 1, out var problem);
        Assert.True(embree is not null, problem);

        int hits = 0;
        foreach (var ray in ThroughputReport.PrimaryRays(40, 30))
        {
            bool ours = bvh.IntersectNearest(ray, double.PositiveInfinity, out double t, out _);
            bool theirs = embree.IntersectNearest(ray, double.PositiveInfinity, out double te, out int primitive);
            Assert.Equal(ours, theirs);
            if (!ours)
                continue;
            hits++;
            // Embree stores the vertices and the ray in float: agreement to float rounding at t ≈ 2.
            Assert.Equal(t, te, 1e-5 * t);
            Assert.InRange(primitive, 0, mesh.TriangleCount - 1);
        }

        Assert.True(hits > 300, $"only {hits} hits");
    }

    [EmbreeFact]
    public void Packets_of_eight_answer_as_single_rays_do()
    {
        var mesh = ThroughputReport.DisplacedSphere(2000);
        using var embree = EmbreeScene.TryCreate(mesh, 1, out var problem);
        Assert.True(embree is not null, problem);

        var rays = ThroughputReport.PrimaryRays(40, 30);
        for (int start = 0; start < rays.Length; start += 7) // 7: packets straddle rows and the last one is short
        {
            var packet = rays.AsSpan(start, Math.Min(8, rays.Length - start));
            int hits = embree.IntersectNearest8(packet, double.PositiveInfinity);
            int occluded = embree.IntersectAny8(packet, 2.5);
            for (int k = 0; k < packet.Length; k++)
            {
                Assert.Equal(embree.IntersectNearest(packet[k], double.PositiveInfinity, out _, out _), (hits & (1 << k)) != 0);
                Assert.Equal(embree.IntersectAny(packet[k], 2.5), (occluded & (1 << k)) != 0);
            }

            Assert.Equal(0, hits >> packet.Length);
        }
    }

    [EmbreeFact]
    public void Any_hit_honours_the_segment_end()
    {
        var mesh = ThroughputReport.DisplacedSphere(2000);
        var bvh = new Bvh(mesh.CreateTriangles(smooth: false));
        using var embree = EmbreeScene.TryCreate(mesh, 1, out var problem);
        Assert.True(embree is not null, problem);

        // From outside towards the centre: the surface (radius about 1) is 2 away.
        var ray = new Ray(new Point3D(0, 0, 3), new Vector3D(0, 0, -1));
        foreach (double tMax in new[] { 1.5, 2.5, 10.0 })
            Assert.Equal(bvh.IntersectAny(ray, tMax), embree.IntersectAny(ray, tMax));
        Assert.False(embree.IntersectAny(ray, 1.5));
        Assert.True(embree.IntersectAny(ray, 2.5));
        Assert.False(embree.IntersectAny(new Ray(new Point3D(0, 0, 3), new Vector3D(0, 0, 1)), 10.0));
    }

    [EmbreeFact]
    public void A_scene_on_another_scenes_device_answers_alike_and_leaves_the_device_to_it()
    {
        var mesh = ThroughputReport.DisplacedSphere(2000);
        var other = ThroughputReport.DisplacedSphere(500);
        using var host = EmbreeScene.TryCreate(mesh, 1, out var problem);
        Assert.True(host is not null, problem);
        var rays = ThroughputReport.PrimaryRays(40, 30);
        using (var same = host.TryCreateOnSameDevice(mesh, out problem))
        {
            Assert.True(same is not null, problem);
            foreach (var ray in rays)
            {
                bool hit = host.IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive);
                Assert.Equal(hit, same.IntersectNearest(ray, double.PositiveInfinity, out double ts, out int primitiveSame));
                Assert.Equal(t, ts);
                Assert.Equal(primitive, primitiveSame);
            }
        }

        // Disposing the second scene must not release the device: the host still answers, and builds again.
        using var again = host.TryCreateOnSameDevice(other, out problem);
        Assert.True(again is not null, problem);
        var centre = new Ray(new Point3D(0, 0, 3), new Vector3D(0, 0, -1));
        Assert.True(host.IntersectNearest(centre, double.PositiveInfinity, out _, out _));
        Assert.True(again.IntersectNearest(centre, double.PositiveInfinity, out _, out _));
    }
}
