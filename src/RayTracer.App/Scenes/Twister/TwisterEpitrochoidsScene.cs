using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Twister;

/// <summary>
/// Thesis Figure 6-9: epitrochoids, a circle of radius r rolling round a fixed circle of radius R with
/// the pen at d from its centre, face on. Top row, R = 3r with the pen inside (d = r/2), on (an
/// epicycloid with three cusps) and outside (loops) the rolling circle; bottom row a cardioid (R = r =
/// d), and two rosettes that close only after several turns (R/r = 5/3 and 7/2).
/// </summary>
public sealed class TwisterEpitrochoidsScene : TwisterGallery
{
    public const double TubeRadius = 0.035, Cell = 2.5;

    /// <summary>(R, r, d, turns) of each cell, row by row.</summary>
    public static readonly (double Fixed, double Rolling, double Pen, double Turns)[] Curves =
    [
        (3, 1, 0.5, 1), (3, 1, 1, 1), (3, 1, 2, 1),
        (1, 1, 1, 1), (5, 3, 2.5, 3), (7, 2, 3, 2),
    ];

    public override string Name => "twister-epitrochoids";
    public override string Description => "Figure 6-9: epitrochoids, epicycloids, a cardioid and rosettes as tubes.";

    protected override void Populate(World world)
    {
        AddFaceOnStudio(world, -2.4);
        for (var k = 0; k < Curves.Length; k++)
        {
            var (fixedRadius, rolling, pen, turns) = Curves[k];
            // Scaled so the curve's outer radius R + r + d is one.
            var scale = 1 / (fixedRadius + rolling + pen);
            var curve = TwistCurves.Epitrochoid(scale * fixedRadius, scale * rolling, scale * pen, turns);
            AddFaceOn(world, [curve], TubeRadius, k, k % 3, k / 3, 3, 2, Cell);
        }

        SetCamera(world, new Point3D(0, 0.6, 10), new Point3D(0, -0.05, 0), 45);
    }
}
