using RayTracer.Geometry.Meshes;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Solvers;

/// <summary>Invocations of each ray–triangle test, counted per thread by the solvers themselves.</summary>
public static class TriangleTestCounters
{
    public static readonly InvocationCounter MollerTrumbore = new("triangle tests (moller)");
    public static readonly InvocationCounter Algebraic = new("triangle tests (algebraic)");
    public static readonly InvocationCounter Plucker = new("triangle tests (plucker)");
    public static readonly InvocationCounter PluckerEdges = new("triangle tests (plucker-edges)");

    public static InvocationCounter For(TriangleTest test) => test switch
    {
        TriangleTest.MollerTrumbore => MollerTrumbore,
        TriangleTest.Algebraic => Algebraic,
        TriangleTest.Plucker => Plucker,
        TriangleTest.PluckerEdges => PluckerEdges,
        _ => throw new ArgumentOutOfRangeException(nameof(test)),
    };
}
