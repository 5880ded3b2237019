using RayTracer.Geometry;
using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Parametric;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Twister;

/// <summary>
/// Thesis Figure 6-8: helixes standing on the ground in two rows. Back: a tight spring, a loose helix,
/// a double helix with rungs (the second strand is the first turned half a turn by a twist of its
/// twists). Front: a conical helix opening upwards, one closing to a point, and a flat spiral (a conical
/// helix of no height) standing face on.
/// </summary>
public sealed class TwisterHelixesScene : TwisterGallery
{
    public const double TubeRadius = 0.045, Height = 1.8;

    public override string Name => "twister-helixes";
    public override string Description => "Figure 6-8: circular, conical and double helixes and a flat spiral as tubes.";

    protected override void Populate(World world)
    {
        AddStage(world, 0);
        Stand(world, 0, -1.2, 0, Upright(Tube(TwistCurves.Helix(0.45, 7, Height), TubeRadius)));
        Stand(world, 1, 0, 0, Upright(Tube(TwistCurves.Helix(0.35, 2.5, Height), TubeRadius)));
        Stand(world, 2, 1.2, 0, Upright(DoubleHelix()));
        Stand(world, 3, -1.2, 1, Upright(Tube(TwistCurves.ConicalHelix(0.08, 0.7, 6, Height), TubeRadius)));
        Stand(world, 4, 0, 1, Upright(Tube(TwistCurves.ConicalHelix(0.7, 0, 8, Height), TubeRadius)));
        Stand(world, 5, 1.2, 1, Tube(TwistCurves.ConicalHelix(0.04, 0.75, 4, 0), TubeRadius));

        AddLights(world, new Point3D(-5, 9, 8));
        SetCamera(world, new Point3D(0, 5.4, 7.4), new Point3D(0, 0.6, 0.2), 50);
    }

    private static void Stand(World world, int colour, double column, int row, GeometricObject shape)
    {
        shape.Material = PaletteMaterial(colour);
        world.Add(StandingAt(shape, 2.3 * column, 2.6 * (row - 0.5)));
    }

    /// <summary>Two strands half a turn apart, joined by a rung every tenth of a turn.</summary>
    private static CompoundObject DoubleHelix()
    {
        const double radius = 0.45, turns = 1.5;
        var strand = TwistCurves.Helix(radius, turns, Height);
        var halfTurn = RotationTwist.AboutZ(Math.PI, ParameterMap.One);
        var other = new TwistCurve(halfTurn.Apply(strand.Seed, 0, 0), strand.Cascade.TransformedBy(halfTurn));
        var helix = new CompoundObject();
        helix.Add(Tube(strand, TubeRadius));
        helix.Add(Tube(other, TubeRadius));
        const int rungs = 15;
        for (var k = 1; k < rungs; k++)
        {
            var t = (double)k / rungs;
            var rung = TwistCurves.LineSegment(strand.PointAt(t), other.PointAt(t));
            helix.Add(Tube(rung, TubeRadius / 2));
        }

        return helix;
    }
}
