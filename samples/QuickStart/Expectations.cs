namespace QuickStart;

/// <summary>The same three results by textbook vector algebra, independent of GMac.</summary>
public static class Expectations
{
    public static Vec3 Normal(Vec3 u, Vec3 v) => u.Cross(v);

    /// <summary>Centre from 2(p_i − a)·c = |p_i|² − |a|² (i = b, c, d) by Cramer's rule; radius |a − c|.</summary>
    public static (Vec3 Centre, double Radius) Sphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d)
    {
        Vec3 r1 = 2 * (b - a), r2 = 2 * (c - a), r3 = 2 * (d - a);
        double k1 = b.Dot(b) - a.Dot(a), k2 = c.Dot(c) - a.Dot(a), k3 = d.Dot(d) - a.Dot(a);
        var det = r1.Dot(r2.Cross(r3));
        // Columns of the inverse are the cross products of the rows divided by the determinant.
        var centre = (1 / det) * (k1 * r2.Cross(r3) + k2 * r3.Cross(r1) + k3 * r1.Cross(r2));
        var offset = a - centre;
        return (centre, Math.Sqrt(offset.Dot(offset)));
    }

    /// <summary>Rodrigues' formula about the unit axis, after moving the line to the origin.</summary>
    public static Vec3 Rotate(Vec3 point, Vec3 through, Vec3 axis, double angle)
    {
        var k = (1 / Math.Sqrt(axis.Dot(axis))) * axis;
        var p = point - through;
        var rotated = Math.Cos(angle) * p + Math.Sin(angle) * k.Cross(p) + (k.Dot(p) * (1 - Math.Cos(angle))) * k;
        return rotated + through;
    }
}
