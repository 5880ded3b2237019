using RayTracer.Colors;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Instancing;

/// <summary>Figure 7-3c: a Twister epitrochoid rosette (R/r = 5/3, three turns) standing face on, 772 tubes.</summary>
public sealed class InstancingEpitrochoidScene : InstancingScene
{
    public const int Segments = 772;

    public override string Name => "instancing-epitrochoid";
    public override string Description => "Figure 7-3c: an epitrochoid rosette as 772 tubes.";

    public override IReadOnlyList<CylinderSpec> Cylinders()
    {
        // Scaled so the outer radius R + r + d is 2.6; the curve stands in the plane z = 0.
        const double fixedRadius = 5, rolling = 3, pen = 2.5;
        var scale = 2.6 / (fixedRadius + rolling + pen);
        var curve = TwistCurves.Epitrochoid(scale * fixedRadius, scale * rolling, scale * pen, 3);
        var points = Enumerable.Range(0, Segments + 1)
            .Select(i => curve.PointAt((double)i / Segments))
            .Select(p => new Point3D(p.x, p.y + 2.9, 0))
            .ToList();
        return Polyline(points, 0.06, TubeMaterial(new RGBColor(0.55, 0.30, 0.65)));
    }

    protected override void Stage(World world)
    {
        AddFloor(world, 0, new RGBColor(0.70, 0.68, 0.64));
        AddLights(world, new Point3D(-3, 8, 9));
        SetCamera(world, new Point3D(0, 3.6, 8.5), new Point3D(0, 2.7, 0), 48, reflections: false);
    }
}
