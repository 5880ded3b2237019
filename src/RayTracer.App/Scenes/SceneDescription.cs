using RayTracer.Geometry;
using RayTracer.Integrators;
using RayTracer.Materials;
using RayTracer.Viewing;

namespace RayTracer.Scenes;

/// <summary>
/// A scene written as a class: it builds a <see cref="World"/> (objects, lights, camera, tracer). Related
/// scenes share set-up by inheritance (one gallery seen through different cameras, one room under
/// different lights).
/// </summary>
public abstract class SceneDescription
{
    /// <summary>Name used on the command line (lower case, dash separated).</summary>
    public abstract string Name { get; }

    public abstract string Description { get; }

    public virtual int DefaultWidth => 400;
    public virtual int DefaultHeight => 300;
    public virtual int DefaultSamples => 16;
    public virtual int DefaultMaxDepth => 5;

    /// <summary>True for scenes that map a user-supplied PNG (<see cref="SceneSettings.ImagePath"/>).</summary>
    public virtual bool UsesImage => false;

    /// <summary>The settings of the current <see cref="Build"/> call.</summary>
    protected SceneSettings Settings { get; private set; } = new();

    public World Build(SceneSettings? settings = null)
    {
        settings ??= new SceneSettings();
        Settings = settings;
        var world = new World
        {
            ViewPlane = new ViewPlane
            {
                HorizontalResolution = settings.Width ?? DefaultWidth,
                VerticalResolution = settings.Height ?? DefaultHeight,
                MaxDepth = settings.MaxDepth ?? DefaultMaxDepth,
                Gamma = 2.2,
            },
        };
        world.ViewPlane.SetSamples(settings.SamplesPerPixel ?? DefaultSamples);
        Populate(world);
        world.FitRayEpsilon();
        if (world.Camera is null || world.Integrator is null)
            throw new InvalidOperationException($"Scene '{Name}' did not set a camera and a tracer.");
        return world;
    }

    /// <summary>Gives an object (often an instance built by chained calls) its material.</summary>
    protected static T WithMaterial<T>(T obj, Material material) where T : GeometricObject
    {
        obj.Material = material;
        return obj;
    }

    /// <summary>Adds objects, lights, camera and tracer; the view plane is already sized.</summary>
    protected abstract void Populate(World world);
}
