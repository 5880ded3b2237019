using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Textures;

namespace RayTracer.Tracing;

/// <summary>
/// Everything shading needs to know about the nearest hit along a ray. A class (not a struct)
/// because it is filled in by objects, passed through materials and lights, and mutated along the way.
/// It knows nothing of the world: integrators trace the rays it spawns.
/// </summary>
public sealed class ShadingRecord
{
    public bool HitAnObject { get; set; }

    public Material? Material { get; set; }

    /// <summary>World-space hit point.</summary>
    public Point3D HitPoint { get; set; }

    /// <summary>Hit point in the object's own frame (before instance transforms), for 3D textures.</summary>
    public Point3D LocalHitPoint { get; set; }

    /// <summary>Unit normal at the hit point, on the outside of the surface.</summary>
    public Normal3D Normal { get; set; }

    public Ray Ray { get; set; }

    /// <summary>Recursion depth of the ray that produced this record.</summary>
    public int Depth { get; set; }

    /// <summary>
    /// Throughput of the path that reached this hit: the product of the reflectances and transmittances
    /// (largest channel) that scale its radiance on the way back to the pixel. 1 for primary rays.
    /// </summary>
    public double Weight { get; set; } = 1.0;

    /// <summary>Ray parameter of the hit.</summary>
    public double T { get; set; }

    /// <summary>Direction towards a sampled light point (area lights).</summary>
    public Vector3D Direction { get; set; }

    public TextureCoordinates TextureCoordinates { get; set; }

    /// <summary>
    /// Hits nearer than this along rays spawned here are ignored: the scene's <see cref="Scenes.World.RayEpsilon"/>,
    /// copied in when the world fills the record.
    /// </summary>
    public double RayEpsilon { get; set; } = MathConstants.Epsilon;

    /// <summary>
    /// A ray leaving the hit point along <paramref name="direction"/> (a unit vector), which ignores hits
    /// nearer than <see cref="RayEpsilon"/> so that it does not find its own surface again.
    /// </summary>
    public Ray SpawnRay(Vector3D direction) => new(HitPoint, direction, RayEpsilon);

    /// <summary>Clears the per-hit state so a record can be reused for another ray.</summary>
    public void Reset()
    {
        HitAnObject = false;
        Material = null;
        HitPoint = default;
        LocalHitPoint = default;
        Normal = default;
        Ray = default;
        Depth = 0;
        Weight = 1.0;
        T = 0;
        Direction = default;
        TextureCoordinates = default;
    }
}
