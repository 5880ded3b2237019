namespace RayTracer.Scenes.Gpcm;

/// <summary>Thesis Figure 6-19: the gallery through the conic generalized pinhole camera.</summary>
public sealed class GpcmConicScene : GpcmGallery
{
    public override string Name => "gpcm-conic";
    public override string Description => "GPCM gallery through a 360-degree cone narrowing upwards (thesis Figure 6-19; conic:180 and conic:90 give Figure 6-20).";
    public override int DefaultWidth => 720;
    public override int DefaultHeight => 240;
    protected override string CameraName => "conic";
    protected override double Degrees => 360;
}
