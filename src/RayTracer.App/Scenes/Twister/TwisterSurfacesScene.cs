using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Parametric;
using RayTracer.Materials;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Twister;

/// <summary>
/// Thesis Figures 6-11 and 6-12: Twister surfaces standing on the ground in two rows. Back: a sphere,
/// a torus, a seashell and a twisted column with a lobed (epitrochoid) cross-section. Front: a cone, a
/// helicoid wearing a (u, v) checker that shows its twist, and a baluster turned from a trochoid (a
/// surface of revolution of a catalogue curve).
/// </summary>
public sealed class TwisterSurfacesScene : TwisterGallery
{
    /// <summary>Largest distance between a surface and its triangles, as a fraction of the surface's size (about 1.6):
    /// about a fifth of a pixel at the default size, fine enough for smooth shading to hide the facets.</summary>
    public const double RelativeTolerance = 3e-3;

    private const double Size = 1.6, Tolerance = RelativeTolerance * Size;

    public override string Name => "twister-surfaces";
    public override string Description => "Figures 6-11, 6-12: sphere, torus, seashell, twisted column, cone, helicoid, turned trochoid.";

    protected override void Populate(World world)
    {
        AddStage(world, 0);
        Stand(world, -3.0, -1.6, Upright(Surface(TwistSurfaces.Sphere(default, Size / 2))), PaletteMaterial(1));
        Stand(world, -1.0, -1.6, Upright(Surface(TwistSurfaces.Torus(0.55, 0.25))), PaletteMaterial(2));
        Stand(world, 1.0, -1.6, Upright(Seashell()), PaletteMaterial(6));
        Stand(world, 3.0, -1.6, Upright(TwistedColumn()), PaletteMaterial(5));
        Stand(world, -2.0, 1.5, Upright(new TessellatedSurface(TwistSurfaces.Cone(0.7, Size), Tolerance)), PaletteMaterial(3));
        var checker = TextureFactory.Checker2D(8, 12, new RGBColor(0.92, 0.90, 0.85), new RGBColor(0.30, 0.40, 0.65));
        Stand(world, 0.0, 1.5, Upright(Surface(TwistSurfaces.Helicoid(0.7, Size, 1))), new TwoSided(MaterialFactory.Plastic(checker, 30)));
        Stand(world, 2.0, 1.5, TurnedTrochoid(), PaletteMaterial(7));

        AddLights(world, new Point3D(-6, 10, 9));
        SetCamera(world, new Point3D(0, 5.6, 7.6), new Point3D(0, 0.5, 0), 56);
    }

    private static TessellatedSurface Surface(IParametricSurface surface) => new(surface, Tolerance);

    private static void Stand(World world, double x, double z, GeometricObject shape, Material material)
    {
        shape.Material = material;
        world.Add(StandingAt(shape, x, z));
    }

    /// <summary>Five whorls, each rising more than the tube is wide and shrinking to a point, scaled to the gallery's size.</summary>
    private static Instance Seashell()
    {
        var shell = TwistSurfaces.Seashell(0.5, 0.3, 5, 4, -1.2);
        const double unscaledSize = 1.6;
        return new Instance(new TessellatedSurface(shell, RelativeTolerance * unscaledSize)).Scale(Size / unscaledSize);
    }

    /// <summary>A six-lobed cross-section (a circle rolling round one six times its radius, pen inside) turned a third of a turn on its way up.</summary>
    private static TessellatedSurface TwistedColumn()
    {
        var section = TwistCurves.Epitrochoid(0.36, 0.06, 0.04, 1);
        return Surface(TwistSurfaces.TwistedColumn(section, Size, 2 * Math.PI / 3));
    }

    /// <summary>
    /// A curtate trochoid along x turned about a line parallel to the x axis just below it (so the waist
    /// stays thick), then stood on end (Twister's x becomes y).
    /// </summary>
    private static Instance TurnedTrochoid()
    {
        var profile = TwistCurves.Trochoid(0.11, 0.07, 2.5);
        var turned = TwistSurfaces.Revolution(profile, new TwistableVector(1, 0, 0), new TwistablePoint(0, -0.15, 0));
        return new Instance(Surface(turned)).RotateZ(Math.PI / 2);
    }
}
