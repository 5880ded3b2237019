namespace RayTracer.Scenes.Gpcm;

/// <summary>Thesis Figure 6-16: the gallery through the rectangular generalized pinhole camera.</summary>
public sealed class GpcmRectangularScene : GpcmGallery
{
    public override string Name => "gpcm-rectangular";
    public override string Description => "GPCM gallery through a 70-degree rectangle, the classic pinhole (thesis Figure 6-16).";
    protected override string CameraName => "rectangular";
    protected override double Degrees => 70;
}
