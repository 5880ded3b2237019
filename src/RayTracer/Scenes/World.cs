using RayTracer.Colors;
using RayTracer.Geometry;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Scenes;

/// <summary>The scene: objects, lights, background and the viewing setup.</summary>
public class World
{
    public IList<GeometricObject> Objects { get; } = new List<GeometricObject>();

    public IList<Light> Lights { get; } = new List<Light>();

    /// <summary>Light added to every material's ambient term; none means no ambient light.</summary>
    public Light? AmbientLight { get; set; }

    /// <summary>Radiance of rays that leave the scene, unless an environment light is set.</summary>
    public RGBColor BackgroundColor { get; set; } = RGBColor.Black;

    /// <summary>When set, rays that leave the scene see its radiance instead of the background colour.</summary>
    public EnvironmentLight? Environment { get; set; }

    public ViewPlane ViewPlane { get; set; } = new();

    public Camera? Camera { get; set; }

    public Tracer? Tracer { get; set; }

    public void Add(GeometricObject obj) => Objects.Add(obj);

    public void Add(Light light) => Lights.Add(light);

    /// <summary>Radiance arriving along a ray that hit nothing.</summary>
    public RGBColor BackgroundRadiance(in Ray ray) => Environment?.Radiance(ray.d) ?? BackgroundColor;

    /// <summary>
    /// Nearest hit over all objects. Clears <paramref name="sr"/> and fills it (world hit point, normal,
    /// material, the ray); returns whether anything was hit.
    /// </summary>
    public bool HitObjects(in Ray ray, ShadingRecord sr)
    {
        RayStatistics.CountRay();
        sr.Reset();
        sr.World = this;
        var tmin = MathConstants.HugeValue;
        Normal3D normal = default;
        Point3D local = default;
        TextureCoordinates uv = default;
        Materials.Material? material = null;
        var objects = Objects;
        for (var i = 0; i < objects.Count; i++)
        {
            var obj = objects[i];
            sr.Material = null;
            if (obj.Hit(ray, out var t, sr) && t < tmin)
            {
                tmin = t;
                // Compounds report the material of the part they hit; simple objects leave it to us.
                material = sr.Material ?? obj.Material;
                normal = sr.Normal;
                local = sr.LocalHitPoint;
                uv = sr.TextureCoordinates;
                sr.HitAnObject = true;
            }
        }
        if (sr.HitAnObject)
        {
            sr.T = tmin;
            sr.HitPoint = ray.At(tmin);
            sr.Normal = normal;
            sr.LocalHitPoint = local;
            sr.TextureCoordinates = uv;
        }
        sr.Material = material;
        sr.Ray = ray;
        return sr.HitAnObject;
    }

    /// <summary>True when a shadow-casting object lies on the ray between its origin and <paramref name="maxDistance"/>.</summary>
    public bool ShadowHit(in Ray ray, double maxDistance)
    {
        RayStatistics.CountRay();
        var objects = Objects;
        for (var i = 0; i < objects.Count; i++)
        {
            var obj = objects[i];
            if (obj.CastsShadows && obj.ShadowHit(ray, out var t) && t < maxDistance)
                return true;
        }
        return false;
    }
}
