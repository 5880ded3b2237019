using RayTracer.Colors;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Instancing;

/// <summary>
/// Figure 7-3d: a Twister twisted column (a four-lobed epitrochoid section lifted while it turns
/// half round) drawn as a cage: 16 strands along the column of 60 tubes each, and four sections of
/// 58 tubes, 1,192 tubes in all.
/// </summary>
public sealed class InstancingColumnScene : InstancingScene
{
    public const int Strands = 16, StrandSegments = 60, Rings = 4, RingSegments = 58;

    public override string Name => "instancing-column";
    public override string Description => "Figure 7-3d: a twisted column as a cage of 1,192 tubes.";

    public override IReadOnlyList<CylinderSpec> Cylinders()
    {
        var section = TwistCurves.Epitrochoid(0.9, 0.3, 0.25, 1);
        var column = TwistSurfaces.TwistedColumn(section, height: 4.2, twistAngle: Math.PI);
        var offset = new Vector3D(0, 0.05, 0);
        var strandMaterial = TubeMaterial(new RGBColor(0.25, 0.60, 0.35));
        var ringMaterial = TubeMaterial(new RGBColor(0.85, 0.45, 0.55));
        var specs = new List<CylinderSpec>();
        for (var s = 0; s < Strands; s++)
        {
            var u = (double)s / Strands;
            specs.AddRange(Polyline(
                [.. Enumerable.Range(0, StrandSegments + 1).Select(i => Upright(column.PointAt(u, (double)i / StrandSegments), 1, offset))],
                0.045, strandMaterial));
        }

        for (var r = 0; r < Rings; r++)
        {
            var v = (r + 0.5) / Rings;
            specs.AddRange(Polyline(
                [.. Enumerable.Range(0, RingSegments + 1).Select(i => Upright(column.PointAt((double)i / RingSegments, v), 1, offset))],
                0.035, ringMaterial));
        }

        return specs;
    }

    protected override void Stage(World world)
    {
        AddFloor(world, 0, new RGBColor(0.70, 0.68, 0.64));
        AddLights(world, new Point3D(-4, 9, 7));
        SetCamera(world, new Point3D(0, 4.6, 9.5), new Point3D(0, 2.0, 0), 46, reflections: false);
    }
}
