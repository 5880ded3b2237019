using RayTracer.Maths;

namespace RayTracer.Textures.Patterns;

/// <summary>
/// Binary checks bounded by meridians and parallels around <see cref="Center"/>: <see cref="NumHorizontal"/>
/// checks around the equator and <see cref="NumVertical"/> from pole to pole, so they do not depend on radius.
/// </summary>
public sealed class SphereChecker(int numHorizontal = 16, int numVertical = 8) : SolidTexture<bool>
{
    public int NumHorizontal { get; set; } = numHorizontal;
    public int NumVertical { get; set; } = numVertical;
    public Point3D Center { get; set; } = Point3D.Origin;

    public override bool Evaluate(Point3D p)
    {
        var d = p - Center;
        var theta = Math.Acos(Math.Clamp(d.y / d.Length, -1, 1));
        var phi = Math.Atan2(d.x, d.z);
        if (phi < 0) phi += MathConstants.TwoPi;
        var i = (int)Math.Floor(phi / MathConstants.TwoPi * NumHorizontal);
        var j = (int)Math.Floor(theta / Math.PI * NumVertical);
        return ((i + j) & 1) == 0;
    }
}
