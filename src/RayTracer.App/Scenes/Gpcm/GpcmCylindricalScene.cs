namespace RayTracer.Scenes.Gpcm;

/// <summary>Thesis Figure 6-17: the gallery through the cylindrical generalized pinhole camera.</summary>
public sealed class GpcmCylindricalScene : GpcmGallery
{
    public override string Name => "gpcm-cylindrical";
    public override string Description => "GPCM gallery through a 360-degree cylinder (thesis Figure 6-17; cylindrical:180 and cylindrical:90 give Figure 6-18).";
    public override int DefaultWidth => 720;
    public override int DefaultHeight => 240;
    protected override string CameraName => "cylindrical";
    protected override double Degrees => 360;
}
