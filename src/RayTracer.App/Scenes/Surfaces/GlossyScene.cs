using RayTracer.Colors;
using RayTracer.Materials;

namespace RayTracer.Scenes.Surfaces;

/// <summary>Glossy reflectors from blurry (low exponent) to sharp (high exponent).</summary>
public sealed class GlossyScene : MaterialsScene
{
    public override string Name => "material-glossy";
    public override string Description => "Glossy reflectors with exponents 10 to 10000 (blurred reflections).";
    public override int DefaultSamples => 36;

    protected override Material MaterialFor(int index) =>
        new GlossyReflector(0.1, 0.2, new RGBColor(0.9, 0.8, 0.5), 0.0, 10 * Math.Pow(10, 0.75 * index), 0.75, new RGBColor(0.95, 0.9, 0.7));
}
