using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>
/// Renders a side-by-side stereo pair with two copies of a camera whose eyes (and look-at points) are
/// moved apart along u so the eye rays subtend <see cref="StereoAngleDegrees"/> at the look-at point.
/// </summary>
public sealed class StereoCamera : Camera
{
    public StereoCamera(Camera left, Camera right)
    {
        Left = left;
        Right = right;
    }

    public Camera Left { get; }
    public Camera Right { get; }
    public double StereoAngleDegrees { get; set; } = 5;
    public int PixelGap { get; set; } = 5;
    public StereoViewing Viewing { get; set; } = StereoViewing.Parallel;

    /// <summary>Places both eyes from this camera's eye, look-at point and up vector.</summary>
    public void SetUpCameras()
    {
        ComputeUVW();
        var r = Eye.Distance(LookAt);
        var x = r * Math.Tan(0.5 * MathConstants.ToRadians(StereoAngleDegrees));
        Left.Eye = Eye - x * U;
        Left.LookAt = LookAt - x * U;
        Right.Eye = Eye + x * U;
        Right.LookAt = LookAt + x * U;
        Left.Up = Right.Up = Up;
        Left.ComputeUVW();
        Right.ComputeUVW();
    }

    public override void Aim() => SetUpCameras();

    public override int ImageWidth(ViewPlane vp) => 2 * vp.HorizontalResolution + PixelGap;

    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray) => Left.GetRay(pp, vp, out ray);

    /// <summary>The first eye fills the left half, the second the right, with a black gap between.</summary>
    public override Camera? EyeFor(ViewPlane vp, int column, out int eyeColumn)
    {
        var hres = vp.HorizontalResolution;
        var first = Viewing == StereoViewing.Parallel ? Left : Right;
        var second = Viewing == StereoViewing.Parallel ? Right : Left;
        eyeColumn = column < hres ? column : column - hres - PixelGap;
        if (column < hres)
            return first;
        return column >= hres + PixelGap ? second : null;
    }
}
