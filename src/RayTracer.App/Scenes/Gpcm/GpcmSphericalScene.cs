namespace RayTracer.Scenes.Gpcm;

/// <summary>Thesis Figure 6-21: the gallery through the spherical generalized pinhole camera.</summary>
public sealed class GpcmSphericalScene : GpcmGallery
{
    public override string Name => "gpcm-spherical";
    public override string Description => "GPCM gallery through a 360x180-degree sphere (thesis Figure 6-21; spherical:180 and spherical:90 give Figure 6-22).";
    public override int DefaultWidth => 720;
    public override int DefaultHeight => 360;
    protected override string CameraName => "spherical";
    protected override double Degrees => 360;
}
