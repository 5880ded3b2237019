using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Scenes;
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

    public override RGBColor RenderPixel(World world, int column, int row)
    {
        var hres = world.ViewPlane.HorizontalResolution;
        var first = Viewing == StereoViewing.Parallel ? Left : Right;
        var second = Viewing == StereoViewing.Parallel ? Right : Left;
        if (column < hres)
            return first.RenderPixel(world, column, row) * Exposure;
        if (column >= hres + PixelGap)
            return second.RenderPixel(world, column - hres - PixelGap, row) * Exposure;
        return RGBColor.Black;
    }
}
