using RayTracer.Colors;
using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Scenes;

namespace RayTracer.Factories;

/// <summary>Creates lights; area lights are added to the world both as a visible object and as a light.</summary>
public static class LightFactory
{
    public static PointLight Point(Point3D location, double radiance, RGBColor? color = null) => new(location, radiance, color);

    public static DirectionalLight Directional(Vector3D towardsLight, double radiance, RGBColor? color = null) => new(towardsLight, radiance, color);

    public static AmbientOccluder AmbientOcclusion(int samples, double radiance = 1.0, double minAmount = 0.0) =>
        new(new MultiJitteredSampler(samples, seed: SamplerSeeds.AmbientOcclusion), radiance, null, minAmount);

    /// <summary>Adds an emissive object as an area light; the object does not cast shadows on its own light.</summary>
    public static AreaLight AddAreaLight<TShape>(World world, TShape shape, double radiance, RGBColor? color = null)
        where TShape : GeometricObject, ISampledShape
    {
        var emitter = new Emissive(radiance, color ?? RGBColor.White);
        shape.Material = emitter;
        shape.CastsShadows = false;
        world.Add(shape);
        var light = new AreaLight(shape, emitter, new MultiJitteredSampler(world.ViewPlane.NumSamples, seed: SamplerSeeds.AreaLight + (ulong)world.Lights.Count));
        world.Add(light);
        return light;
    }

    public static AreaLight AddRectangleLight(World world, Point3D corner, Vector3D a, Vector3D b, double radiance, RGBColor? color = null) =>
        AddAreaLight(world, new Rectangle(corner, a, b), radiance, color);

    public static AreaLight AddDiskLight(World world, Point3D center, Normal3D normal, double radius, double radiance, RGBColor? color = null) =>
        AddAreaLight(world, new Disk(center, normal, radius), radiance, color);

    public static AreaLight AddSphereLight(World world, Point3D center, double radius, double radiance, RGBColor? color = null) =>
        AddAreaLight(world, new Sphere(center, radius), radiance, color);

    /// <summary>Uniform sky: lights the scene (sampled) and is seen by rays that escape.</summary>
    public static EnvironmentLight AddEnvironment(World world, double radiance, RGBColor? color = null, int samples = 64)
    {
        var light = new EnvironmentLight(new MultiJitteredSampler(samples, seed: SamplerSeeds.Environment), radiance, color);
        world.Environment = light;
        world.Add(light);
        return light;
    }
}
