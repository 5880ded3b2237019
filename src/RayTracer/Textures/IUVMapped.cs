using RayTracer.Textures.Mappings;

namespace RayTracer.Textures;

/// <summary>A texture defined on 2D texture space (u, v), reached through an optional mapping of the hit point.</summary>
public interface IUVMapped<out T>
{
    TextureMapping? Mapping { get; }

    T Evaluate(double u, double v);
}
