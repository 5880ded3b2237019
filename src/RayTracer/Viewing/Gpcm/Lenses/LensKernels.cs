using System.Runtime.CompilerServices;
using RayTracer.Maths;

namespace RayTracer.Viewing;

/// <summary>
/// One generated kernel per catalogue lens (dsl/macros/gpcm.gmac): rest-frame surface point and turn
/// into the world composed, returning the unit ray direction from the eye.
/// </summary>
internal static class LensKernels
{
    /// <summary>Through the point (x, y) of the rectangle at <paramref name="distance"/> ahead.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Rectangle(double x, double y, double distance, GpcmOrientation orientation)
    {
        var right = orientation.Right;
        var up = orientation.Up;
        var back = orientation.Back;
        var d = new Vector3D();

        #region GMac : RectangleLensRay
        //GMac.Bind("x.1", x);
        //GMac.Bind("y.1", y);
        //GMac.Bind("distance.1", distance);
        //GMac.Bind("right", "Vector3D", right);
        //GMac.Bind("up", "Vector3D", up);
        //GMac.Bind("back", "Vector3D", back);
        //GMac.Bind("d", "Vector3D", d);
        double tmp0 = 1.0 / Math.Sqrt(x * x + y * y + distance * distance);
        double tmp1 = distance * tmp0;
        double tmp2 = y * tmp0;
        double tmp3 = x * tmp0;
        d.x = right.x * tmp3 + up.x * tmp2 - back.x * tmp1;
        d.y = right.y * tmp3 + up.y * tmp2 - back.y * tmp1;
        d.z = right.z * tmp3 + up.z * tmp2 - back.z * tmp1;
        #endregion

        return d;
    }

    /// <summary>Towards <paramref name="azimuth"/> right of and <paramref name="elevation"/> above the look direction.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Sphere(double azimuth, double elevation, GpcmOrientation orientation)
    {
        var right = orientation.Right;
        var up = orientation.Up;
        var back = orientation.Back;
        var d = new Vector3D();

        #region GMac : SphereLensRay
        //GMac.Bind("azimuth.1", azimuth);
        //GMac.Bind("elevation.1", elevation);
        //GMac.Bind("right", "Vector3D", right);
        //GMac.Bind("up", "Vector3D", up);
        //GMac.Bind("back", "Vector3D", back);
        //GMac.Bind("d", "Vector3D", d);
        var (tmp0, tmp1) = Math.SinCos(elevation);
        var (tmp2, tmp3) = Math.SinCos(azimuth);
        double tmp4 = tmp1 * tmp2;
        double tmp5 = tmp1 * tmp3;
        d.x = tmp0 * up.x + tmp4 * right.x - tmp5 * back.x;
        d.y = tmp0 * up.y + tmp4 * right.y - tmp5 * back.y;
        d.z = tmp0 * up.z + tmp4 * right.z - tmp5 * back.z;
        #endregion

        return d;
    }

    /// <summary>Through the point at <paramref name="height"/> of the ring of <paramref name="radius"/> about up, <paramref name="azimuth"/> right of ahead.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Ring(double azimuth, double height, double radius, GpcmOrientation orientation)
    {
        var right = orientation.Right;
        var up = orientation.Up;
        var back = orientation.Back;
        var d = new Vector3D();

        #region GMac : RingLensRay
        //GMac.Bind("azimuth.1", azimuth);
        //GMac.Bind("height.1", height);
        //GMac.Bind("radius.1", radius);
        //GMac.Bind("right", "Vector3D", right);
        //GMac.Bind("up", "Vector3D", up);
        //GMac.Bind("back", "Vector3D", back);
        //GMac.Bind("d", "Vector3D", d);
        double tmp0 = 1.0 / Math.Sqrt(height * height + radius * radius);
        var (tmp1, tmp2) = Math.SinCos(azimuth);
        double tmp3 = radius * tmp0;
        double tmp4 = tmp1 * tmp3;
        double tmp5 = height * tmp0;
        double tmp6 = tmp2 * tmp3;
        d.x = tmp4 * right.x + tmp5 * up.x - tmp6 * back.x;
        d.y = tmp4 * right.y + tmp5 * up.y - tmp6 * back.y;
        d.z = tmp4 * right.z + tmp5 * up.z - tmp6 * back.z;
        #endregion

        return d;
    }

    /// <summary>
    /// <paramref name="angleFromAxis"/> away from the look direction, towards the image direction whose
    /// cosine and sine are <paramref name="c"/> and <paramref name="s"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Cap(double c, double s, double angleFromAxis, GpcmOrientation orientation)
    {
        var right = orientation.Right;
        var up = orientation.Up;
        var back = orientation.Back;
        var d = new Vector3D();

        #region GMac : CapLensRay
        //GMac.Bind("c.1", c);
        //GMac.Bind("s.1", s);
        //GMac.Bind("angleFromAxis.1", angleFromAxis);
        //GMac.Bind("right", "Vector3D", right);
        //GMac.Bind("up", "Vector3D", up);
        //GMac.Bind("back", "Vector3D", back);
        //GMac.Bind("d", "Vector3D", d);
        var (tmp0, tmp1) = Math.SinCos(angleFromAxis);
        double tmp2 = tmp0 * s;
        double tmp3 = tmp0 * c;
        d.x = tmp2 * up.x + tmp3 * right.x - tmp1 * back.x;
        d.y = tmp2 * up.y + tmp3 * right.y - tmp1 * back.y;
        d.z = tmp2 * up.z + tmp3 * right.z - tmp1 * back.z;
        #endregion

        return d;
    }
}
