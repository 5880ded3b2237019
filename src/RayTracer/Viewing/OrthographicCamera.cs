using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>Parallel projection: all rays travel along -w from points on the view plane through the eye.</summary>
public sealed class OrthographicCamera : Camera
{
    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        ray = new Ray(Eye + pp.x * U + pp.y * V, -W);
        return true;
    }
}
