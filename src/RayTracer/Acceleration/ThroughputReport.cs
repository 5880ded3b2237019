using System.Diagnostics;
using System.Globalization;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// Measures build time and primary-ray throughput (nearest hit only, no shading) of every
/// acceleration structure on a procedural, finely tessellated displaced sphere.
/// </summary>
public static class ThroughputReport
{
    private const int TimedPasses = 3;

    public static void Run(TextWriter output, int triangles, int width, int height, int threads)
    {
        ArgumentNullException.ThrowIfNull(output);
        ArgumentOutOfRangeException.ThrowIfLessThan(triangles, 8);
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(threads, 1);
        var culture = CultureInfo.InvariantCulture;

        var clock = Stopwatch.StartNew();
        var mesh = DisplacedSphere(triangles);
        GeometricObject[] primitives = mesh.CreateTriangles(smooth: false);
        output.WriteLine(string.Create(culture,
            $"mesh: displaced sphere, {mesh.TriangleCount:N0} triangles, {mesh.Vertices.Length:N0} vertices ({clock.Elapsed.TotalSeconds:F2} s)"));
        output.WriteLine(string.Create(culture,
            $"rays: {width}x{height} primary rays, 1 per pixel, nearest hit only, {threads} thread(s), {Environment.ProcessorCount} logical processor(s), best of {TimedPasses} passes"));

        var builders = new (string Name, Func<GeometricObject[], AccelerationStructure> Build)[]
        {
            ("regular grid", p => new RegularGrid(p)),
            ("BIH", p => new BoundingIntervalHierarchy(p)),
            ("SAH BVH", p => new Bvh(p)),
        };

        foreach (var (name, build) in builders)
        {
            GC.Collect();
            clock.Restart();
            var structure = build(primitives);
            double buildSeconds = clock.Elapsed.TotalSeconds;

            // A small warm-up pass lets the JIT settle before timing; then the best of three passes
            // is reported, which filters out interference from other work on the machine.
            CastPrimaryRays(structure, Math.Max(1, width / 8), Math.Max(1, height / 8), threads);
            double rays = width * (double)height;
            double bestWall = double.PositiveInfinity, bestCpu = double.PositiveInfinity;
            long hits = 0;
            for (int pass = 0; pass < TimedPasses; pass++)
            {
                var cpuBefore = Process.GetCurrentProcess().TotalProcessorTime;
                clock.Restart();
                hits = CastPrimaryRays(structure, width, height, threads);
                bestWall = Math.Min(bestWall, clock.Elapsed.TotalSeconds);
                bestCpu = Math.Min(bestCpu, (Process.GetCurrentProcess().TotalProcessorTime - cpuBefore).TotalSeconds);
            }

            // Wall-clock rate is what a user sees; the per-CPU-second rate does not depend on how
            // busy the machine is with other work, which makes runs on shared machines comparable.
            output.WriteLine(string.Create(culture,
                $"{name,-14} build {buildSeconds,7:F2} s   cast {bestWall,7:F3} s   {rays / bestWall / 1e6,7:F2} Mrays/s   {rays / bestCpu / 1e6,7:F2} Mrays per CPU-second   hits {hits:N0}"));
        }
    }

    /// <summary>Casts one ray through each pixel centre from a pinhole camera on the +z axis; returns the hit count.</summary>
    public static long CastPrimaryRays(IRayIntersector structure, int width, int height, int threads)
    {
        var eye = new Point3D(0, 0, 3.2);
        double halfHeight = Math.Tan(0.5 * MathConstants.ToRadians(45));
        double halfWidth = halfHeight * width / height;
        long hits = 0;
        Parallel.For(
            0,
            height,
            new ParallelOptions { MaxDegreeOfParallelism = threads },
            () => 0L,
            (row, state, local) =>
            {
                double y = halfHeight * (1 - 2 * (row + 0.5) / height);
                for (int col = 0; col < width; col++)
                {
                    double x = halfWidth * (2 * (col + 0.5) / width - 1);
                    var ray = new Ray(eye, new Vector3D(x, y, -1));
                    if (structure.IntersectNearest(ray, double.PositiveInfinity, out _, out _))
                    {
                        local++;
                    }
                }

                return local;
            },
            local => Interlocked.Add(ref hits, local));
        return hits;
    }

    /// <summary>
    /// Closed latitude–longitude sphere of at least <paramref name="triangles"/> triangles (single
    /// vertices at the poles) whose radius is modulated by a smooth bump pattern, so the surface is
    /// not trivially convex.
    /// </summary>
    public static Mesh DisplacedSphere(int triangles)
    {
        // segments = 2 · rings gives 2 · segments · (rings - 1) = 4 rings (rings - 1) triangles.
        int rings = Math.Max(2, (int)Math.Ceiling((1 + Math.Sqrt(1 + triangles)) / 2));
        while (4L * rings * (rings - 1) < triangles)
        {
            rings++;
        }

        int segments = 2 * rings;
        var vertices = new Point3D[2 + (rings - 1) * segments];
        vertices[0] = new Point3D(0, Radius(0, 0), 0);
        vertices[^1] = new Point3D(0, -Radius(Math.PI, 0), 0);
        for (int i = 1; i < rings; i++)
        {
            double theta = Math.PI * i / rings;
            for (int j = 0; j < segments; j++)
            {
                double phi = MathConstants.TwoPi * j / segments;
                double r = Radius(theta, phi);
                vertices[Ring(i, j, segments)] = new Point3D(
                    r * Math.Sin(theta) * Math.Cos(phi), r * Math.Cos(theta), r * Math.Sin(theta) * Math.Sin(phi));
            }
        }

        var indices = new int[6 * segments * (rings - 1)];
        int k = 0, south = vertices.Length - 1;
        for (int j = 0; j < segments; j++)
        {
            int next = (j + 1) % segments;
            // Polar fans, wound so that the normals (v1 - v0) × (v2 - v0) point outward.
            indices[k++] = 0;
            indices[k++] = Ring(1, next, segments);
            indices[k++] = Ring(1, j, segments);
            indices[k++] = south;
            indices[k++] = Ring(rings - 1, j, segments);
            indices[k++] = Ring(rings - 1, next, segments);
            for (int i = 1; i < rings - 1; i++)
            {
                int a = Ring(i, j, segments), b = Ring(i, next, segments);
                int c = Ring(i + 1, j, segments), d = Ring(i + 1, next, segments);
                indices[k++] = a;
                indices[k++] = b;
                indices[k++] = c;
                indices[k++] = b;
                indices[k++] = d;
                indices[k++] = c;
            }
        }

        return new Mesh(vertices, indices);
    }

    private static int Ring(int ring, int segment, int segments) => 1 + (ring - 1) * segments + segment;

    // The bumps vanish towards the poles (factor sin θ), so the pole vertices are well defined.
    private static double Radius(double theta, double phi) =>
        1 + Math.Sin(theta) * (0.06 * Math.Sin(7 * theta) * Math.Cos(9 * phi) + 0.02 * Math.Sin(23 * theta + 3 * phi));
}
