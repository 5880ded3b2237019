using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Twister;

/// <summary>
/// Thesis Figure 6-7: the basic Twister curves as tubes, face on in front of a backdrop. Top row: a
/// pentagram of line segments, a circle, concentric arcs; bottom row: a square spiral of segments, a
/// wave of half-circle arcs, and circles turned about the vertical by a twist applied to their twists.
/// </summary>
public sealed class TwisterCurvesScene : TwisterGallery
{
    public const double TubeRadius = 0.05, Cell = 2.5;

    public override string Name => "twister-curves";
    public override string Description => "Figure 6-7: line segments, a circle, arcs and twisted circles as tubes.";

    protected override void Populate(World world)
    {
        AddFaceOnStudio(world, -2.4);
        Place(world, 0, 0, Pentagram());
        Place(world, 1, 0, [TwistCurves.Circle(default, 1)]);
        Place(world, 2, 0, ConcentricArcs());
        Place(world, 0, 1, SquareSpiral());
        Place(world, 1, 1, ArcWave());
        Place(world, 2, 1, TurnedCircles());

        SetCamera(world, new Point3D(0, 0.6, 10), new Point3D(0, -0.05, 0), 45);
    }

    private static void Place(World world, int column, int row, IReadOnlyList<TwistCurve> curves) =>
        AddFaceOn(world, curves, TubeRadius, column + 3 * row, column, row, 3, 2, Cell);

    private static TwistCurve[] Pentagram()
    {
        var corners = Enumerable.Range(0, 5)
            .Select(k => Math.PI / 2 + 4 * Math.PI * k / 5)
            .Select(a => new TwistablePoint(Math.Cos(a), Math.Sin(a), 0))
            .ToArray();
        return [.. Enumerable.Range(0, 5).Select(k => TwistCurves.LineSegment(corners[k], corners[(k + 1) % 5]))];
    }

    private static TwistCurve[] ConcentricArcs() =>
    [
        TwistCurves.Arc(default, 1.0, 0, 1.5 * Math.PI),
        TwistCurves.Arc(default, 0.7, Math.PI / 2, Math.PI),
        TwistCurves.Arc(default, 0.4, Math.PI, Math.PI / 2),
    ];

    /// <summary>Segments turning left by a right angle, each a little longer than the one before.</summary>
    private static TwistCurve[] SquareSpiral()
    {
        var curves = new List<TwistCurve>();
        var at = new TwistablePoint(0, 0, 0);
        for (var k = 0; k < 9; k++)
        {
            var length = 0.22 * (k + 1);
            var angle = Math.PI / 2 * k;
            var next = new TwistablePoint(at.x + length * Math.Cos(angle), at.y + length * Math.Sin(angle), 0);
            curves.Add(TwistCurves.LineSegment(at, next));
            at = next;
        }

        return [.. curves];
    }

    /// <summary>Half circles alternately above and below the line, joined end to end.</summary>
    private static TwistCurve[] ArcWave()
    {
        const double r = 0.25;
        return [.. Enumerable.Range(0, 4).Select(k => k % 2 == 0
            ? TwistCurves.Arc(new(r * (2 * k + 1), 0, 0), r, Math.PI, -Math.PI)
            : TwistCurves.Arc(new(r * (2 * k + 1), 0, 0), r, Math.PI, Math.PI))];
    }

    /// <summary>One circle in the x-y plane and copies of it turned about the y axis: each copy's twists are the circle's twists moved by the turn.</summary>
    private static TwistCurve[] TurnedCircles()
    {
        var circle = TwistCurves.Circle(default, 0.95);
        return [.. Enumerable.Range(0, 4).Select(k =>
        {
            var turn = RotationTwist.AboutY(Math.PI / 4 * k + 0.35, ParameterMap.One);
            return new TwistCurve(turn.Apply(circle.Seed, 0, 0), circle.Cascade.TransformedBy(turn));
        })];
    }
}
