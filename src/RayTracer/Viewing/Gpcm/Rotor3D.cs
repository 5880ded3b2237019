namespace RayTracer.Viewing;

/// <summary>A rotor of 3D space, R = s + xy e1^e2 + yz e2^e3 + zx e3^e1; unit when s² + xy² + yz² + zx² = 1.</summary>
public struct Rotor3D(double s, double xy, double yz, double zx)
{
    public double s = s;
    public double xy = xy;
    public double yz = yz;
    public double zx = zx;

    public static Rotor3D Identity => new(1, 0, 0, 0);

    public override readonly string ToString() => FormattableString.Invariant($"{s} + {xy} e12 + {yz} e23 + {zx} e31");
}
