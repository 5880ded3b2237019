using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Viewing;

namespace RayTracer.Factories;

/// <summary>Creates cameras with their frame computed, sized to the view plane they will render.</summary>
public static class CameraFactory
{
    public static PinholeCamera Pinhole(Point3D eye, Point3D lookAt, double horizontalFovDegrees, ViewPlane vp)
    {
        var camera = new PinholeCamera { Eye = eye, LookAt = lookAt };
        camera.SetHorizontalFieldOfView(horizontalFovDegrees, vp);
        camera.ComputeUVW();
        return camera;
    }

    /// <summary>Orthographic view whose image width spans <paramref name="viewWidth"/> world units.</summary>
    public static OrthographicCamera Orthographic(Point3D eye, Point3D lookAt, double viewWidth, ViewPlane vp)
    {
        vp.PixelSize = viewWidth / vp.HorizontalResolution;
        var camera = new OrthographicCamera { Eye = eye, LookAt = lookAt };
        camera.ComputeUVW();
        return camera;
    }

    public static ThinLensCamera ThinLens(Point3D eye, Point3D lookAt, double horizontalFovDegrees, double focalDistance, double lensRadius, ViewPlane vp)
    {
        var viewDistance = 0.5 * vp.HorizontalResolution * vp.PixelSize / Math.Tan(MathConstants.ToRadians(horizontalFovDegrees) / 2);
        var camera = new ThinLensCamera
        {
            Eye = eye, LookAt = lookAt, ViewDistance = viewDistance, FocalDistance = focalDistance, LensRadius = lensRadius,
            LensSampler = new MultiJitteredSampler(vp.NumSamples, seed: SamplerSeeds.Lens),
        };
        camera.ComputeUVW();
        return camera;
    }

    public static FisheyeCamera Fisheye(Point3D eye, Point3D lookAt, double fovDegrees)
    {
        var camera = new FisheyeCamera { Eye = eye, LookAt = lookAt, MaxPsiDegrees = fovDegrees / 2 };
        camera.ComputeUVW();
        return camera;
    }

    public static SphericalCamera Spherical(Point3D eye, Point3D lookAt, double horizontalDegrees = 360, double verticalDegrees = 180)
    {
        var camera = new SphericalCamera { Eye = eye, LookAt = lookAt, MaxLambdaDegrees = horizontalDegrees / 2, MaxPsiDegrees = verticalDegrees / 2 };
        camera.ComputeUVW();
        return camera;
    }

    /// <summary>Stereo pair of pinhole cameras; each half of the image has the view plane's width.</summary>
    public static StereoCamera Stereo(Point3D eye, Point3D lookAt, double horizontalFovDegrees, double stereoAngleDegrees, ViewPlane vp)
    {
        var left = Pinhole(eye, lookAt, horizontalFovDegrees, vp);
        var right = Pinhole(eye, lookAt, horizontalFovDegrees, vp);
        var stereo = new StereoCamera(left, right) { Eye = eye, LookAt = lookAt, StereoAngleDegrees = stereoAngleDegrees };
        stereo.SetUpCameras();
        return stereo;
    }
}
