using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>
/// A camera with an orthonormal frame (u, v, w) built from eye, look-at point and up vector; w points
/// from the look-at point back to the eye. Subclasses map view-plane points to primary rays.
/// </summary>
public abstract class Camera
{
    public Point3D Eye { get; set; } = new(0, 0, 500);
    public Point3D LookAt { get; set; } = Point3D.Origin;
    public Vector3D Up { get; set; } = Vector3D.UnitY;

    /// <summary>Scales radiance (a stand-in for exposure time).</summary>
    public double Exposure { get; set; } = 1.0;

    public Vector3D U { get; private set; } = Vector3D.UnitX;
    public Vector3D V { get; private set; } = Vector3D.UnitY;
    public Vector3D W { get; private set; } = Vector3D.UnitZ;

    /// <summary>Builds (u, v, w); handles looking straight up or down, where up × w vanishes.</summary>
    public void ComputeUVW()
    {
        var w = (Eye - LookAt);
        if (w.LengthSquared == 0)
            throw new InvalidOperationException("Camera eye and look-at point coincide.");
        w.Normalize();
        var u = Up.Cross(w);
        if (u.LengthSquared < 1e-20)
        {
            // Up is parallel to the viewing direction: pick a fixed frame around the vertical.
            var sign = w.y > 0 ? 1.0 : -1.0;
            U = new Vector3D(0, 0, sign);
            V = new Vector3D(1, 0, 0);
            W = new Vector3D(0, sign, 0);
            return;
        }
        u.Normalize();
        U = u;
        V = w.Cross(u);
        W = w;
    }

    /// <summary>
    /// Recomputes whatever the camera derives from <see cref="Eye"/>, <see cref="LookAt"/> and
    /// <see cref="Up"/>; call after changing them. Cameras with more to derive (the generalized pinhole
    /// camera's rotor, a stereo pair's two eyes) override it.
    /// </summary>
    public virtual void Aim() => ComputeUVW();

    /// <summary>Width of the rendered image in pixels (stereo pairs are wider than the view plane).</summary>
    public virtual int ImageWidth(ViewPlane vp) => vp.HorizontalResolution;

    public virtual int ImageHeight(ViewPlane vp) => vp.VerticalResolution;

    /// <summary>
    /// Primary ray through view-plane point <paramref name="pp"/> (origin at the centre of the view plane,
    /// y up). Returns false where the camera sees nothing (outside a fisheye circle).
    /// </summary>
    public abstract bool GetRay(Point2D pp, ViewPlane vp, out Ray ray);

    /// <summary>
    /// The camera whose rays fill image column <paramref name="column"/>, and that column in its own image:
    /// this camera itself, except for cameras made of several eyes. Null where no camera sees (a gap).
    /// </summary>
    public virtual Camera? EyeFor(ViewPlane vp, int column, out int eyeColumn)
    {
        eyeColumn = column;
        return this;
    }
}
