namespace RayTracer.Tests.Geometry.Solvers;

/// <summary>Tests that read the global per-test invocation counters run one at a time.</summary>
[CollectionDefinition(Name)]
public sealed class TriangleTestCollection
{
    public const string Name = "Triangle tests";
}
