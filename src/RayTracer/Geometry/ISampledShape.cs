using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry;

/// <summary>
/// A surface that can be sampled uniformly by area, which is what an area light needs of its shape.
/// Only shapes with a known area and a normal at every sample implement it, so an area light cannot be
/// built on anything else.
/// </summary>
public interface ISampledShape
{
    /// <summary>Maps a uniform sample of the unit square onto the surface, uniformly by area.</summary>
    Point3D Sample(Point2D unitSquareSample);

    /// <summary>Area density of <see cref="Sample"/>: 1 / surface area.</summary>
    double Pdf(ShadingRecord sr);

    /// <summary>Outward unit normal at a point produced by <see cref="Sample"/>.</summary>
    Normal3D GetNormal(Point3D p);
}
