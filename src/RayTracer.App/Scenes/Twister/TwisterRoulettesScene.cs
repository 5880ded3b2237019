using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Twister;

/// <summary>
/// Thesis Figure 6-10, face on. Top row, hypotrochoids (a circle rolling inside another): a
/// spirograph star, a deltoid and an astroid. Middle row, roses ρ = cos kφ with k = 2, 3 and 4/3.
/// Bottom row, trochoids (a circle rolling on a line): curtate, a cycloid and prolate.
/// </summary>
public sealed class TwisterRoulettesScene : TwisterGallery
{
    public const double TubeRadius = 0.03, Cell = 2.3;

    public override string Name => "twister-roulettes";
    public override string Description => "Figure 6-10: hypotrochoids, roses and trochoids as tubes.";

    protected override void Populate(World world)
    {
        AddFaceOnStudio(world, -3.6);
        TwistCurve[] curves =
        [
            Hypotrochoid(5, 3, 5, 3), Hypotrochoid(3, 1, 1, 1), Hypotrochoid(4, 1, 1, 1),
            TwistCurves.Rose(1, 2, 1), TwistCurves.Rose(1, 3, 0.5), TwistCurves.Rose(1, 4.0 / 3, 3),
            Trochoid(0.5), Trochoid(1), Trochoid(1.7),
        ];
        for (var k = 0; k < curves.Length; k++)
        {
            AddFaceOn(world, [curves[k]], TubeRadius, k, k % 3, k / 3, 3, 3, Cell);
        }

        SetCamera(world, new Point3D(0, 0.4, 10.5), new Point3D(0, -0.05, 0), 49);
    }

    /// <summary>A hypotrochoid scaled so its outer radius |R − r| + d is one.</summary>
    private static TwistCurve Hypotrochoid(double fixedRadius, double rolling, double pen, double turns)
    {
        var scale = 1 / (Math.Abs(fixedRadius - rolling) + pen);
        return TwistCurves.Hypotrochoid(scale * fixedRadius, scale * rolling, scale * pen, turns);
    }

    /// <summary>One and a half turns of a trochoid whose pen is <paramref name="penRatio"/> rolling radii from the centre, two units long.</summary>
    private static TwistCurve Trochoid(double penRatio)
    {
        const double turns = 1.5, rolling = 2 / (2 * Math.PI * turns);
        return TwistCurves.Trochoid(rolling, penRatio * rolling, turns);
    }
}
