using RayTracer.Maths;

namespace RayTracer.Textures;

/// <summary>A texture defined on 3D space, evaluated at a (local) point.</summary>
public interface IUVWMapped<out T>
{
    T Evaluate(Point3D p);
}
