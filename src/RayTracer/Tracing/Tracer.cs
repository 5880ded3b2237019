using RayTracer.Util;

namespace RayTracer.Tracing;

/// <summary>Computes the radiance carried back along a ray.</summary>
public abstract class Tracer
{
    public abstract RGBColor TraceRay(in Ray ray, int depth);
}
