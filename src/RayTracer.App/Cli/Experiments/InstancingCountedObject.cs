using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Materials;
using RayTracer.Tracing;

namespace RayTracer.Cli.Experiments;

/// <summary>
/// Counts every intersection test asked of the wrapped tube, then hands it on; with a log, also
/// records the test so that it can be asked again of the bare tube and timed. Used only in the
/// counting render, so the timed renders run the tubes bare. The log is not thread safe: record
/// with one render thread.
/// </summary>
internal sealed class InstancingCountedObject(GeometricObject inner, InvocationCounter counter,
    int index = 0, List<InstancingRecordedTest>? log = null) : GeometricObject
{
    public GeometricObject Inner => inner;

    public override Material? Material
    {
        get => inner.Material;
        set => inner.Material = value;
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        counter.Increment();
        log?.Add(new(index, InstancingTestKind.Hit, ray, 0));
        return inner.Hit(ray, out tmin, sr);
    }

    public override bool Intersect(in Ray ray, out double t)
    {
        counter.Increment();
        log?.Add(new(index, InstancingTestKind.Intersect, ray, 0));
        return inner.Intersect(ray, out t);
    }

    public override bool ShadowHit(in Ray ray, out double tmin)
    {
        counter.Increment();
        log?.Add(new(index, InstancingTestKind.ShadowHit, ray, 0));
        return inner.ShadowHit(ray, out tmin);
    }

    public override bool Occludes(in Ray ray, double maxDistance)
    {
        counter.Increment();
        log?.Add(new(index, InstancingTestKind.Occludes, ray, maxDistance));
        return inner.Occludes(ray, maxDistance);
    }

    public override BoundingBox GetBoundingBox() => inner.GetBoundingBox();
}
