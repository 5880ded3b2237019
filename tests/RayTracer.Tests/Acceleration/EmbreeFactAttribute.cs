using RayTracer.Acceleration.Embree;

namespace RayTracer.Tests.Acceleration;

/// <summary>A fact that runs only where libembree3.so.3 loads; elsewhere it is skipped with the reason.</summary>
internal sealed class EmbreeFactAttribute : FactAttribute
{
    public EmbreeFactAttribute()
    {
        if (!EmbreeLibrary.TryLoad(out var problem))
            Skip = $"Embree is not available: {problem}";
    }
}
