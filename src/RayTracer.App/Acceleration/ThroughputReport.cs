using System.Diagnostics;
using System.Globalization;
using System.Numerics;
using RayTracer.Acceleration.Embree;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Scenes.Meshes;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// Measures build time and primary-ray throughput (nearest hit only, no shading) of every acceleration
/// structure on one mesh (a procedural, finely tessellated displaced sphere, or a mesh file), then shadow
/// rays (any hit) from the BVH's primary hits; Embree 3 casts the same rays at the same mesh alongside
/// when <c>libembree3.so.3</c> is installed.
/// </summary>
public static class ThroughputReport
{
    private const int TimedPasses = 3;
    private const double MinPassSeconds = 0.2;
    private const int MaxRepeats = 64;

    // Builds compared with Embree's: at least this many, then more until they have taken MinPassSeconds.
    private const int MinBuilds = 3;
    private const int MaxBuilds = 16;

    // Rays per work item of the parallel loops: a row of the default image.
    private const int ChunkSize = 1024;

    // Shadow rays start this fraction of the mesh's bounding radius off the surface, on the side the
    // camera sees: far beyond float rounding, so both libraries agree on which rays leave the surface.
    private const double ShadowOffset = 1e-4;

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
        output.WriteLine(string.Create(culture,
            $"mesh: displaced sphere, {mesh.TriangleCount:N0} triangles, {mesh.Vertices.Length:N0} vertices ({clock.Elapsed.TotalSeconds:F2} s)"));
        Measure(output, mesh, PrimaryRays(width, height), $"{width}x{height} primary rays, 1 per pixel", threads);
    }

    /// <summary>
    /// As <see cref="Run(TextWriter, int, int, int, int)"/> on <paramref name="mesh"/> with the given primary
    /// rays (for example from a camera), described in the output as <paramref name="rayDescription"/>.
    /// </summary>
    public static void Run(TextWriter output, Mesh mesh, string meshName, Ray[] rays, string rayDescription, int threads)
    {
        ArgumentNullException.ThrowIfNull(output);
        ArgumentNullException.ThrowIfNull(mesh);
        ArgumentNullException.ThrowIfNull(rays);
        ArgumentOutOfRangeException.ThrowIfLessThan(threads, 1);
        output.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"mesh: {meshName}, {mesh.TriangleCount:N0} triangles, {mesh.Vertices.Length:N0} vertices"));
        Measure(output, mesh, rays, rayDescription, threads);
    }

    private static void Measure(TextWriter output, Mesh mesh, Ray[] rays, string rayDescription, int threads)
    {
        var culture = CultureInfo.InvariantCulture;
        GeometricObject[] primitives = mesh.CreateTriangles(smooth: false);
        output.WriteLine(string.Create(culture,
            $"rays: {rayDescription}, nearest hit only, {threads} thread(s), {Environment.ProcessorCount} logical processor(s), best of {TimedPasses} passes, each repeating the ray set for {MinPassSeconds} s or more (at most {MaxRepeats} times), times per ray set"));
        output.WriteLine(string.Create(culture,
            $"builds: SAH BVH and Embree alike, the fastest of {MinBuilds} or more (until {MinPassSeconds} s, at most {MaxBuilds}) after an untimed one, Embree's on its already started device; grid and BIH built once"));

        var builders = new (string Name, Func<GeometricObject[], AccelerationStructure> Build)[]
        {
            ("regular grid", p => new RegularGrid(p)),
            ("BIH", p => new BoundingIntervalHierarchy(p)),
            ("SAH BVH", p => new Bvh(p)),
        };

        AccelerationStructure? bvh = null;
        Timing bvhPrimary = default;
        BuildTiming bvhBuild = default;
        foreach (var (name, build) in builders)
        {
            // The BVH, compared with Embree below, is timed as Embree is (see TimeBuild); the others are built once.
            var (structure, buildTiming) = name == "SAH BVH" ? TimeBuild(() => build(primitives)) : TimeOnce(() => build(primitives));
            var timing = Time(new Nearest(structure), rays, double.PositiveInfinity, threads);
            output.WriteLine(Row(name, buildTiming, timing, rays.Length, "hits"));
            bvh = structure;
            bvhPrimary = timing;
            bvhBuild = buildTiming;
        }

        // The BVH's primary hits, untimed, give the shadow rays both libraries cast.
        var shadowRays = ShadowRays(bvh!, mesh, rays, threads, out var light);

        // A first scene, untimed, loads the library and starts the device's threads; the timed scenes are
        // built on that device, as ours run on a thread pool that is already started.
        using var host = EmbreeScene.TryCreate(mesh, threads, out string? problem);
        EmbreeScene? embree = null;
        BuildTiming embreeBuild = default;
        if (host is not null)
            (embree, embreeBuild) = TimeBuild(() => host.TryCreateOnSameDevice(mesh, out problem));
        using var embreeScope = embree;
        Timing embreePrimary = default, embreeShadow = default;
        if (embree is null)
        {
            output.WriteLine($"{"Embree",-20} skipped: {problem}");
        }
        else
        {
            embreePrimary = Time(new Nearest(embree), rays, double.PositiveInfinity, threads);
            output.WriteLine(Row("Embree rtcIntersect1", embreeBuild, embreePrimary, rays.Length, "hits"));
            long differ = CountDisagreements(new Nearest(bvh!), new Nearest(embree), rays, double.PositiveInfinity, threads);
            output.WriteLine(Comparison(bvhPrimary, embreePrimary, "hits", differ, "rtcIntersect1"));
            var packets = Time(new EmbreePackets(embree, anyHit: false), rays, double.PositiveInfinity, threads);
            output.WriteLine(Row("Embree rtcIntersect8", null, packets, rays.Length, "hits"));
            differ = CountDisagreements(new Nearest(bvh!), new EmbreePackets(embree, anyHit: false), rays, double.PositiveInfinity, threads);
            output.WriteLine(Comparison(bvhPrimary, packets, "hits", differ, "rtcIntersect8"));
        }

        output.WriteLine(string.Create(culture,
            $"shadow rays: {shadowRays.Length:N0}, from the SAH BVH's primary hits towards a point light at ({light.x:G4}, {light.y:G4}, {light.z:G4}), any hit"));
        var bvhShadow = Time(new Any(bvh!), shadowRays, 1.0, threads);
        output.WriteLine(Row("SAH BVH any hit", null, bvhShadow, shadowRays.Length, "occluded"));
        if (embree is not null)
        {
            embreeShadow = Time(new Any(embree), shadowRays, 1.0, threads);
            output.WriteLine(Row("Embree rtcOccluded1", null, embreeShadow, shadowRays.Length, "occluded"));
            long differ = CountDisagreements(new Any(bvh!), new Any(embree), shadowRays, 1.0, threads);
            output.WriteLine(Comparison(bvhShadow, embreeShadow, "occluded", differ, "rtcOccluded1"));
            var packets = Time(new EmbreePackets(embree, anyHit: true), shadowRays, 1.0, threads);
            output.WriteLine(Row("Embree rtcOccluded8", null, packets, shadowRays.Length, "occluded"));
            differ = CountDisagreements(new Any(bvh!), new EmbreePackets(embree, anyHit: true), shadowRays, 1.0, threads);
            output.WriteLine(Comparison(bvhShadow, packets, "occluded", differ, "rtcOccluded8"));
            output.WriteLine(Summary(bvhPrimary, embreePrimary, bvhShadow, embreeShadow, bvhBuild, embreeBuild));
        }
    }

    /// <summary>
    /// The three figures the BVH is judged by, each ours against Embree's single-ray calls in this run:
    /// primary and shadow throughput as a fraction of Embree's (per CPU-second, which other work on the
    /// machine disturbs least, and wall clock), and build time as a multiple of Embree's.
    /// </summary>
    private static string Summary(Timing primary, Timing embreePrimary, Timing shadow, Timing embreeShadow, BuildTiming build, BuildTiming embreeBuild) =>
        string.Create(CultureInfo.InvariantCulture, $"""
            ratios, SAH BVH against Embree in this run:
              primary rays (rtcIntersect1)  {embreePrimary.Cpu / primary.Cpu,5:F2} of Embree's Mrays per CPU-second ({embreePrimary.Wall / primary.Wall:F2} wall)   goal >= 0.80
              shadow rays (rtcOccluded1)    {embreeShadow.Cpu / shadow.Cpu,5:F2} of Embree's Mrays per CPU-second ({embreeShadow.Wall / shadow.Wall:F2} wall)
              build time                    {build.Wall / embreeBuild.Wall,5:F2} times Embree's wall-clock time ({build.Cpu / embreeBuild.Cpu:F2} of its CPU time)   goal <= 1.50
            """);

    /// <summary>
    /// How ours and Embree's builds are timed alike: one untimed build first (it compiles our code, or
    /// warms Embree's), then builds until there are <see cref="MinBuilds"/> and they have taken
    /// <see cref="MinPassSeconds"/> (at most <see cref="MaxBuilds"/>), each after a full collection with
    /// the previous result released; the fastest counts, wall clock and process CPU time separately.
    /// </summary>
    private static (T Result, BuildTiming Timing) TimeBuild<T>(Func<T> build)
    {
        var clock = new Stopwatch();
        var result = build();
        BuildTiming best = new(double.PositiveInfinity, double.PositiveInfinity);
        double total = 0;
        for (int i = 0; i < MaxBuilds && (i < MinBuilds || total < MinPassSeconds); i++)
        {
            (result as IDisposable)?.Dispose();
            result = default!;
            GC.Collect();
            var cpuBefore = Environment.CpuUsage.TotalTime;
            clock.Restart();
            result = build();
            double wall = clock.Elapsed.TotalSeconds, cpu = (Environment.CpuUsage.TotalTime - cpuBefore).TotalSeconds;
            total += wall;
            best = new BuildTiming(Math.Min(best.Wall, wall), Math.Min(best.Cpu, cpu));
        }

        return (result, best);
    }

    /// <summary>A single build, timed (the structures not compared with Embree).</summary>
    private static (T Result, BuildTiming Timing) TimeOnce<T>(Func<T> build)
    {
        GC.Collect();
        var cpuBefore = Environment.CpuUsage.TotalTime;
        var clock = Stopwatch.StartNew();
        var result = build();
        return (result, new BuildTiming(clock.Elapsed.TotalSeconds, (Environment.CpuUsage.TotalTime - cpuBefore).TotalSeconds));
    }

    private static string Row(string name, BuildTiming? buildTiming, Timing timing, int rays, string counted)
    {
        // Wall-clock rate is what a user sees; the per-CPU-second rate does not depend on how
        // busy the machine is with other work, which makes runs on shared machines comparable.
        // Milliseconds with two decimals, so that a small mesh's build of about a millisecond still reads.
        string build = buildTiming is { } b ? string.Create(CultureInfo.InvariantCulture, $"build {b.Wall * 1e3,8:F2} ms {b.Cpu * 1e3,8:F2} CPU-ms") : new string(' ', 33);
        return string.Create(CultureInfo.InvariantCulture,
            $"{name,-20} {build}   cast {timing.Wall,7:F3} s   {rays / timing.Wall / 1e6,7:F2} Mrays/s   {rays / timing.Cpu / 1e6,7:F2} Mrays per CPU-second   {counted} {timing.Count:N0}");
    }

    private static string Comparison(Timing ours, Timing embree, string counted, long differ, string function)
    {
        string agreement = ours.Count == embree.Count && differ == 0
            ? $"{counted} agree ray by ray ({ours.Count:N0})"
            : $"{counted} DIFFER: ours {ours.Count:N0}, Embree {embree.Count:N0}, {differ:N0} ray(s) answered differently";
        return string.Create(CultureInfo.InvariantCulture,
            $"  SAH BVH / {function}: {embree.Wall / ours.Wall:F2} of its Mrays/s, {embree.Cpu / ours.Cpu:F2} of its Mrays per CPU-second; {agreement}");
    }

    /// <summary>
    /// A small warm-up pass lets the JIT settle; a timed pass then casts the rays as many times as it takes
    /// to last <see cref="MinPassSeconds"/> (at most <see cref="MaxRepeats"/>), so that small meshes are not
    /// timed at the clocks' resolution; the best of three passes, per cast of the ray set, filters out
    /// interference from other work.
    /// </summary>
    private static Timing Time<TCaster>(TCaster caster, Ray[] rays, double tMax, int threads)
        where TCaster : struct, IRayCaster
    {
        Count(caster, rays, Math.Min(rays.Length, Math.Max(1, rays.Length / 64)), tMax, threads);
        var clock = Stopwatch.StartNew();
        long count = Count(caster, rays, rays.Length, tMax, threads);
        int repeats = (int)Math.Clamp(Math.Ceiling(MinPassSeconds / Math.Max(clock.Elapsed.TotalSeconds, 1e-9)), 1, MaxRepeats);
        double bestWall = double.PositiveInfinity, bestCpu = double.PositiveInfinity;
        for (int pass = 0; pass < TimedPasses; pass++)
        {
            // Environment.CpuUsage reads getrusage (microseconds); Process.TotalProcessorTime counts clock ticks.
            var cpuBefore = Environment.CpuUsage.TotalTime;
            clock.Restart();
            for (int r = 0; r < repeats; r++)
                Count(caster, rays, rays.Length, tMax, threads);
            bestWall = Math.Min(bestWall, clock.Elapsed.TotalSeconds / repeats);
            bestCpu = Math.Min(bestCpu, (Environment.CpuUsage.TotalTime - cpuBefore).TotalSeconds / repeats);
        }

        return new Timing(bestWall, Math.Max(bestCpu, 1e-9), count);
    }

    /// <summary>How many of the first <paramref name="count"/> rays the caster answers true for.</summary>
    private static long Count<TCaster>(TCaster caster, Ray[] rays, int count, double tMax, int threads)
        where TCaster : struct, IRayCaster
    {
        long total = 0;
        Parallel.For(
            0,
            (count + ChunkSize - 1) / ChunkSize,
            new ParallelOptions { MaxDegreeOfParallelism = threads },
            () => 0L,
            (chunk, _, local) =>
            {
                int start = chunk * ChunkSize;
                return local + caster.Cast(rays.AsSpan(start, Math.Min(count, start + ChunkSize) - start), tMax, []);
            },
            local => Interlocked.Add(ref total, local));
        return total;
    }

    /// <summary>Rays answered differently, compared chunk by chunk so that packets are cast as in the timed passes.</summary>
    private static long CountDisagreements<TOurs, TTheirs>(TOurs ours, TTheirs theirs, Ray[] rays, double tMax, int threads)
        where TOurs : struct, IRayCaster
        where TTheirs : struct, IRayCaster
    {
        long differ = 0;
        Parallel.For(0, (rays.Length + ChunkSize - 1) / ChunkSize, new ParallelOptions { MaxDegreeOfParallelism = threads }, chunk =>
        {
            int start = chunk * ChunkSize, n = Math.Min(rays.Length, start + ChunkSize) - start;
            var a = new bool[n];
            var b = new bool[n];
            ours.Cast(rays.AsSpan(start, n), tMax, a);
            theirs.Cast(rays.AsSpan(start, n), tMax, b);
            int local = 0;
            for (int i = 0; i < n; i++)
                local += a[i] != b[i] ? 1 : 0;
            Interlocked.Add(ref differ, local);
        });
        return differ;
    }

    /// <summary>
    /// A ray from each primary hit towards a point light above and to the left of the studio camera's
    /// direction, 6 bounding radii from the mesh's centre; direction light − origin, so the light is at t = 1.
    /// </summary>
    private static Ray[] ShadowRays(AccelerationStructure bvh, Mesh mesh, Ray[] primary, int threads, out Point3D light)
    {
        var (centre, radius) = MeshStudioScene.BoundingSphere(mesh);
        var target = centre + 6 * radius * MeshStudioScene.Direction(MeshStudioScene.AzimuthDegrees - 50, 55);
        light = target;
        var shadow = new Ray?[primary.Length];
        Parallel.For(0, primary.Length, new ParallelOptions { MaxDegreeOfParallelism = threads }, i =>
        {
            ref readonly var ray = ref primary[i];
            if (!bvh.IntersectNearest(ray, double.PositiveInfinity, out double t, out int hit) || bvh.GetPrimitive(hit) is not ITriangle tri)
                return;
            var normal = Vector3D.Cross(tri.V1 - tri.V0, tri.V2 - tri.V0).Normalized();
            if (Vector3D.Dot(normal, ray.d) > 0)
                normal = -normal;
            var origin = ray.At(t) + ShadowOffset * radius * normal;
            shadow[i] = new Ray(origin, target - origin);
        });
        return [.. shadow.Where(r => r.HasValue).Select(r => r!.Value)];
    }

    /// <summary>One ray through each pixel centre from a pinhole camera on the +z axis with a 45° vertical field of view.</summary>
    public static Ray[] PrimaryRays(int width, int height)
    {
        var eye = new Point3D(0, 0, 3.2);
        double halfHeight = Math.Tan(0.5 * MathConstants.ToRadians(45));
        double halfWidth = halfHeight * width / height;
        var rays = new Ray[width * height];
        for (int row = 0; row < height; row++)
        {
            double y = halfHeight * (1 - 2 * (row + 0.5) / height);
            for (int col = 0; col < width; col++)
            {
                double x = halfWidth * (2 * (col + 0.5) / width - 1);
                rays[row * width + col] = new Ray(eye, new Vector3D(x, y, -1));
            }
        }

        return rays;
    }

    /// <summary>Casts the rays of <see cref="PrimaryRays"/> at the structure; returns the hit count.</summary>
    public static long CastPrimaryRays(IRayIntersector structure, int width, int height, int threads)
    {
        var rays = PrimaryRays(width, height);
        return Count(new Nearest(structure), rays, rays.Length, double.PositiveInfinity, threads);
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

    private readonly record struct Timing(double Wall, double Cpu, long Count);

    private readonly record struct BuildTiming(double Wall, double Cpu);

    /// <summary>
    /// Queries for a run of rays, returning how many found a hit and, when <c>answers</c> is not empty, each
    /// ray's answer; structs, so that the generic loops compile to direct calls.
    /// </summary>
    private interface IRayCaster
    {
        int Cast(ReadOnlySpan<Ray> rays, double tMax, Span<bool> answers);
    }

    private readonly struct Nearest(IRayQueries structure) : IRayCaster
    {
        public int Cast(ReadOnlySpan<Ray> rays, double tMax, Span<bool> answers)
        {
            int count = 0;
            for (int i = 0; i < rays.Length; i++)
            {
                bool hit = structure.IntersectNearest(rays[i], tMax, out _, out _);
                count += hit ? 1 : 0;
                if (!answers.IsEmpty)
                    answers[i] = hit;
            }

            return count;
        }
    }

    private readonly struct Any(IRayQueries structure) : IRayCaster
    {
        public int Cast(ReadOnlySpan<Ray> rays, double tMax, Span<bool> answers)
        {
            int count = 0;
            for (int i = 0; i < rays.Length; i++)
            {
                bool hit = structure.IntersectAny(rays[i], tMax);
                count += hit ? 1 : 0;
                if (!answers.IsEmpty)
                    answers[i] = hit;
            }

            return count;
        }
    }

    /// <summary>Packets of 8 consecutive rays (neighbouring pixels of a row), nearest hit or any hit.</summary>
    private readonly struct EmbreePackets(EmbreeScene scene, bool anyHit) : IRayCaster
    {
        public int Cast(ReadOnlySpan<Ray> rays, double tMax, Span<bool> answers)
        {
            int count = 0;
            for (int i = 0; i < rays.Length; i += 8)
            {
                int n = Math.Min(8, rays.Length - i);
                var packet = rays.Slice(i, n);
                int mask = anyHit ? scene.IntersectAny8(packet, tMax) : scene.IntersectNearest8(packet, tMax);
                count += BitOperations.PopCount((uint)mask);
                for (int k = 0; k < n && !answers.IsEmpty; k++)
                    answers[i + k] = (mask & (1 << k)) != 0;
            }

            return count;
        }
    }
}
