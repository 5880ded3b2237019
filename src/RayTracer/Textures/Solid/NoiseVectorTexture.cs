using RayTracer.Maths;
using RayTracer.Textures.Noise;

namespace RayTracer.Textures.Solid;

/// <summary>
/// Vector solid texture: three decorrelated fractal sums (the noise sampled at shifted points), each in
/// [-1, 1]; useful for perturbing normals or directions.
/// </summary>
public sealed class NoiseVectorTexture(LatticeNoise noise, double scale = 1.0) : SolidTexture<Vector3D>
{
    private static readonly Vector3D OffsetY = new(31.416, 7.389, 2.718);
    private static readonly Vector3D OffsetZ = new(-17.32, 44.72, 12.25);

    public LatticeNoise Noise { get; } = noise;
    public double Scale { get; set; } = scale;

    public override Vector3D Evaluate(Point3D p)
    {
        var q = p * Scale;
        double Component(Vector3D offset) => 2 * Noise.Fbm(q.x + offset.x, q.y + offset.y, q.z + offset.z) - 1;
        return new Vector3D(Component(Vector3D.Zero), Component(OffsetY), Component(OffsetZ));
    }
}
