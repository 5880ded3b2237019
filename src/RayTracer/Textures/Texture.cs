using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Textures;

/// <summary>
/// A value that varies over a surface. The four kinds of the design are the type arguments: binary
/// (<c>bool</c>), colour (<see cref="RGBColor"/>), scalar (<c>double</c>) and vector (<see cref="Vector3D"/>).
/// </summary>
public abstract class Texture<T>
{
    public abstract T GetValue(ShadingRecord sr);
}
