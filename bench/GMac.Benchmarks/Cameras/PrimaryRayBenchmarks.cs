using System.Runtime.CompilerServices;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;
using RayTracer.Factories;
using RayTracer.Maths;
using RayTracer.Viewing;

namespace GMac.Benchmarks.Cameras;

/// <summary>
/// Primary-ray generation of the generalized pinhole cameras (thesis §6.5) against the hand-derived
/// cameras they reproduce, each building <see cref="Rays"/> rays through random view-plane points of a
/// 640×360 image from the same eye, look-at point and up direction. Results are per ray; each category
/// compares a GPCM with its hand camera (the baseline). The cylindrical and conic panoramas have no hand
/// counterpart and are listed for scale. The "Cascade" rows are the same GPCMs taking every ray the
/// general way any surface takes (Twister cascade, then the turn into the world) instead of their
/// generated lens kernel.
/// </summary>
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
[CategoriesColumn]
public class PrimaryRayBenchmarks
{
    public const int Rays = 4096;

    private readonly Point2D[] _points = new Point2D[Rays];
    private readonly ViewPlane _plane = new() { HorizontalResolution = 640, VerticalResolution = 360, PixelSize = 1 };
    private readonly Dictionary<string, Camera> _cameras = [];

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(20261123);
        for (var i = 0; i < Rays; i++)
            _points[i] = new Point2D((random.NextDouble() - 0.5) * 640, (random.NextDouble() - 0.5) * 360);
        var eye = new Point3D(1, 2, 3);
        var lookAt = new Point3D(-4, 1, -6);
        var up = new Vector3D(0.1, 1, 0.2);
        foreach (var (name, degrees) in new[] { ("pinhole", 60.0), ("rectangular", 60), ("spherical-hand", 360), ("spherical", 360), ("fisheye-hand", 180), ("fisheye", 180), ("cylindrical", 360), ("conic", 360) })
        {
            if (!CameraCatalog.TryFind(name, out var choice))
                throw new InvalidOperationException($"no camera '{name}'");
            _cameras[name] = choice.Create(degrees, _plane, eye, lookAt, up);
            if (_cameras[name] is Gpcm)
            {
                // The same camera taking every ray the general way (cascade, then the turn into the world).
                var general = (Gpcm)choice.Create(degrees, _plane, eye, lookAt, up);
                general.EvaluateThroughCascade = true;
                _cameras[name + "-cascade"] = general;
            }
        }
    }

    // Inlined into every benchmark, so each has its own call site to GetRay: with one shared loop the
    // JIT's profile of that call site mixes every camera run before in the same process, and a
    // camera's figure depended on which others had run (the in-process toolchain shares the JIT).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private double Sweep(string name)
    {
        var camera = _cameras[name];
        var sum = 0.0;
        foreach (var pp in _points)
            if (camera.GetRay(pp, _plane, out var ray))
                sum += ray.d.x + ray.d.y + ray.d.z;
        return sum;
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Rays), BenchmarkCategory("rectangular")]
    public double Pinhole() => Sweep("pinhole");

    [Benchmark(OperationsPerInvoke = Rays), BenchmarkCategory("rectangular")]
    public double RectangularGpcm() => Sweep("rectangular");

    [Benchmark(OperationsPerInvoke = Rays), BenchmarkCategory("rectangular")]
    public double RectangularGpcmCascade() => Sweep("rectangular-cascade");

    [Benchmark(Baseline = true, OperationsPerInvoke = Rays), BenchmarkCategory("spherical")]
    public double SphericalHand() => Sweep("spherical-hand");

    [Benchmark(OperationsPerInvoke = Rays), BenchmarkCategory("spherical")]
    public double SphericalGpcm() => Sweep("spherical");

    [Benchmark(OperationsPerInvoke = Rays), BenchmarkCategory("spherical")]
    public double SphericalGpcmCascade() => Sweep("spherical-cascade");

    [Benchmark(Baseline = true, OperationsPerInvoke = Rays), BenchmarkCategory("fisheye")]
    public double FisheyeHand() => Sweep("fisheye-hand");

    [Benchmark(OperationsPerInvoke = Rays), BenchmarkCategory("fisheye")]
    public double FisheyeGpcm() => Sweep("fisheye");

    [Benchmark(OperationsPerInvoke = Rays), BenchmarkCategory("fisheye")]
    public double FisheyeGpcmCascade() => Sweep("fisheye-cascade");

    [Benchmark(Baseline = true, OperationsPerInvoke = Rays), BenchmarkCategory("panoramas")]
    public double CylindricalGpcm() => Sweep("cylindrical");

    [Benchmark(OperationsPerInvoke = Rays), BenchmarkCategory("panoramas")]
    public double ConicGpcm() => Sweep("conic");
}
