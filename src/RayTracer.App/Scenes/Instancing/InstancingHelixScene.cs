using RayTracer.Colors;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Instancing;

/// <summary>Figure 7-3b: a Twister helix (thesis (6.6)) of five turns drawn with 333 tubes.</summary>
public sealed class InstancingHelixScene : InstancingScene
{
    public const int Segments = 333;

    public override string Name => "instancing-helix";
    public override string Description => "Figure 7-3b: a helix of five turns as 333 tubes.";

    public override IReadOnlyList<CylinderSpec> Cylinders()
    {
        var helix = TwistCurves.Helix(radius: 1.4, turns: 5, height: 4);
        var points = Enumerable.Range(0, Segments + 1)
            .Select(i => Upright(helix.PointAt((double)i / Segments), 1, new Vector3D(0, 0.3, 0)))
            .ToList();
        return Polyline(points, 0.16, TubeMaterial(new RGBColor(0.90, 0.65, 0.15)));
    }

    protected override void Stage(World world)
    {
        AddFloor(world, 0, new RGBColor(0.70, 0.68, 0.64));
        AddLights(world, new Point3D(-4, 9, 7));
        SetCamera(world, new Point3D(0, 4.5, 9), new Point3D(0, 2.2, 0), 45, reflections: false);
    }
}
