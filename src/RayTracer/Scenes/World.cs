using RayTracer.Bounds;
using RayTracer.Colors;
using RayTracer.Geometry;
using RayTracer.Integrators;
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

    /// <summary>The light transport algorithm: it traces the rays and samples the lights.</summary>
    public Integrator? Integrator { get; set; }

    /// <summary>
    /// Hits nearer than this along a ray from a surface (or the eye) are ignored, against rounding
    /// ("shadow acne"). <see cref="FitRayEpsilon"/> scales it with the scene; until then it is
    /// <see cref="MathConstants.Epsilon"/>, right for scenes a few units across.
    /// </summary>
    public double RayEpsilon { get; set; } = MathConstants.Epsilon;

    /// <summary>
    /// Sets <see cref="RayEpsilon"/> once for this scene: <see cref="MathConstants.Epsilon"/> times the
    /// largest side of the bounded objects' box, so that a mesh a nanometre or ten million kilometres
    /// across renders as a unit one does; and never below what rounding at the scene's distance from
    /// the origin needs. Unbounded objects (planes) do not count; with none bounded it stays as it is.
    /// </summary>
    public void FitRayEpsilon()
    {
        var box = BoundingBox.Empty;
        foreach (var obj in Objects)
        {
            var bounds = obj.GetBoundingBox();
            if (!bounds.IsEmpty && bounds.IsFinite)
                box.Include(bounds);
        }
        if (box.IsEmpty)
            return;
        var size = Math.Max(box.Diagonal.x, Math.Max(box.Diagonal.y, box.Diagonal.z));
        var reach = Math.Max(MaxAbs(box.Min), MaxAbs(box.Max));
        // Doubles carry 16 digits: a relative 1e-12 of the coordinates leaves a wide margin over their rounding.
        var epsilon = Math.Max(MathConstants.Epsilon * size, Tolerances.RelativeRounding * reach);
        if (epsilon > 0 && double.IsFinite(epsilon))
            RayEpsilon = epsilon;
    }

    private static double MaxAbs(Point3D p) => Math.Max(Math.Abs(p.x), Math.Max(Math.Abs(p.y), Math.Abs(p.z)));

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
        sr.RayEpsilon = RayEpsilon;
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
