using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>
/// Depth of field: rays start on a lens disk of radius <see cref="LensRadius"/> and pass through the point
/// of the focal plane (distance <see cref="FocalDistance"/>) that the pinhole ray would hit.
/// </summary>
public sealed class ThinLensCamera : Camera
{
    private Sampler _lensSampler;

    public ThinLensCamera()
    {
        _lensSampler = new MultiJitteredSampler(16, seed: SamplerSeeds.Lens);
        _lensSampler.MapSamplesToUnitDisk();
    }

    public double LensRadius { get; set; } = 1.0;
    public double ViewDistance { get; set; } = 500;
    public double FocalDistance { get; set; } = 500;
    public double Zoom { get; set; } = 1.0;

    public Sampler LensSampler
    {
        get => _lensSampler;
        set
        {
            value.MapSamplesToUnitDisk();
            _lensSampler = value;
        }
    }

    /// <summary>Ray from lens point <paramref name="lensPoint"/> (unit disk) through the focal-plane image of <paramref name="pp"/>.</summary>
    public Ray RayThrough(Point2D pp, Point2D lensPoint)
    {
        var dp = lensPoint * LensRadius;
        var px = pp.x / Zoom * FocalDistance / ViewDistance;
        var py = pp.y / Zoom * FocalDistance / ViewDistance;
        var d = (px - dp.x) * U + (py - dp.y) * V - FocalDistance * W;
        return new Ray(Eye + dp.x * U + dp.y * V, d.Normalized());
    }

    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        ray = RayThrough(pp, _lensSampler.SampleUnitDisk());
        return true;
    }
}
