using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Textures.Conversions;
using RayTracer.Textures.Noise;
using RayTracer.Textures.Patterns;
using RayTracer.Textures.Solid;

namespace RayTracer.Factories;

/// <summary>Colour textures assembled from the pattern, noise and conversion building blocks.</summary>
public static class TextureFactory
{
    public static Texture<RGBColor> Constant(RGBColor color) => new ConstantTexture<RGBColor>(color);

    public static Texture<RGBColor> Checker3D(double size, RGBColor a, RGBColor b) => new BinaryColorTexture(new Checker3D(size), a, b);

    public static Texture<RGBColor> PlaneChecker(double size, RGBColor a, RGBColor b) => new BinaryColorTexture(new PlaneChecker(size), a, b);

    public static Texture<RGBColor> SphereChecker(int around, int poleToPole, RGBColor a, RGBColor b, Point3D? center = null) =>
        new BinaryColorTexture(new SphereChecker(around, poleToPole) { Center = center ?? Point3D.Origin }, a, b);

    public static Texture<RGBColor> Checker2D(int numU, int numV, RGBColor a, RGBColor b) => new BinaryColorTexture(new Checker2D(numU, numV), a, b);

    public static Texture<RGBColor> Noise(NoiseKind kind, RGBColor low, RGBColor high, double scale = 1, int octaves = 6, bool cubic = true, int seed = 253)
    {
        LatticeNoise noise = cubic ? new CubicNoise(octaves, seed: seed) : new LinearNoise(octaves, seed: seed);
        return new ScalarColorTexture(new NoiseTexture(noise, kind, scale), low, high);
    }

    public static Texture<RGBColor> Marble(int seed = 253) =>
        new RampTexture(new CubicNoise(6, seed: seed),
            [new RGBColor(0.25, 0.22, 0.2), new RGBColor(0.9, 0.88, 0.85), new RGBColor(0.95, 0.95, 0.95), new RGBColor(0.6, 0.55, 0.5)],
            amplitude: 6, frequency: 3);

    public static Texture<RGBColor> Wood(int seed = 253) =>
        new WoodTexture(new CubicNoise(4, seed: seed), new RGBColor(0.85, 0.62, 0.35), new RGBColor(0.45, 0.25, 0.1));
}
