namespace RayTracer.Scenes.Gpcm;

/// <summary>Thesis Figure 6-23: the gallery through the fisheye generalized pinhole camera.</summary>
public sealed class GpcmFisheyeScene : GpcmGallery
{
    public override string Name => "gpcm-fisheye";
    public override string Description => "GPCM gallery through a 360-degree sphere cap, polar mapping (thesis Figure 6-23; fisheye:180 and fisheye:90 give Figure 6-24).";
    public override int DefaultWidth => 360;
    public override int DefaultHeight => 360;
    protected override string CameraName => "fisheye";
    protected override double Degrees => 360;
}
