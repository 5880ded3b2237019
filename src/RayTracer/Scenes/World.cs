using RayTracer.Geometry;
using RayTracer.Lights;
using RayTracer.Tracing;
using RayTracer.Util;
using RayTracer.Viewing;

namespace RayTracer.Scenes;

/// <summary>The scene: objects, lights and the viewing setup.</summary>
public abstract class World
{
    public abstract IList<GeometricObject> Objects { get; }

    public abstract IList<Light> Lights { get; }

    public abstract Light? AmbientLight { get; set; }

    public abstract RGBColor BackgroundColor { get; set; }

    public abstract ViewPlane? ViewPlane { get; set; }

    public abstract Camera? Camera { get; set; }

    public abstract Tracer? Tracer { get; set; }

    /// <summary>Nearest hit over all objects, as a filled shading record.</summary>
    public abstract ShadingRecord HitObjects(in Ray ray);
}
