using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Parametric;
using RayTracer.Materials;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Twister;

/// <summary>
/// Thesis Figure 6-1: one cylinder from two generating algorithms, wearing the same (u, v) checker. On
/// the left a helix in u swept about the axis in v, so the checks wind round as helical bands; on the
/// right a circle in u lifted along the axis in v, so they form rings and columns.
/// </summary>
public sealed class TwisterCylindersScene : TwisterGallery
{
    public const double Radius = 0.8, Height = 2.0, HelixTurns = 1.0;

    public override string Name => "twister-cylinders";
    public override string Description => "Figure 6-1: a helix-swept and a circle-lifted cylinder under one (u, v) checker.";

    protected override void Populate(World world)
    {
        AddStage(world, 0);
        var checker = TextureFactory.Checker2D(12, 6, new RGBColor(0.92, 0.90, 0.85), new RGBColor(0.75, 0.22, 0.18));
        var material = new TwoSided(MaterialFactory.Plastic(checker, 30));
        var tolerance = 1e-3 * Height;

        var helixSwept = new TessellatedSurface(TwistSurfaces.HelixCylinder(Radius, Height, HelixTurns), tolerance) { Material = material };
        var circleLifted = new TessellatedSurface(TwistSurfaces.CircleCylinder(Radius, Height), tolerance) { Material = material };
        world.Add(StandingAt(Upright(helixSwept), -1.15, 0));
        world.Add(StandingAt(Upright(circleLifted), 1.15, 0));

        AddLights(world, new Point3D(-4, 7, 6));
        SetCamera(world, new Point3D(0, 2.8, 6.2), new Point3D(0, 0.95, 0), 48);
    }
}
