namespace GMac.Benchmarks.Kernels.Values;

/// <summary>Three 3D vectors: a basis, or the columns of a matrix.</summary>
public struct Vec3Triple
{
    public Vec3 A;
    public Vec3 B;
    public Vec3 C;
}
