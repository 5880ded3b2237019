namespace RayTracer.Cli.Experiments;

/// <summary>Which of a tube's tests was called.</summary>
internal enum InstancingTestKind : byte
{
    Intersect,
    Hit,
    ShadowHit,
    Occludes,
}
