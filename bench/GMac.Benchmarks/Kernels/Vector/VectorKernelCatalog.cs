namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>The vector form of every kernel of <see cref="KernelCatalog"/>, in the report's order.</summary>
public static class VectorKernelCatalog
{
    private static readonly Dictionary<string, Func<VectorKernel>> Factories = new(StringComparer.Ordinal)
    {
        ["HiddenSurface"] = () => new HiddenSurfaceVectorKernel(),
        ["VortexS"] = () => new VortexSVectorKernel(),
        ["Circ3"] = () => new Circ3VectorKernel(),
        ["GramSchmidtContraction"] = () => new GramSchmidtContractionVectorKernel(),
        ["GramSchmidtRejection"] = () => new GramSchmidtRejectionVectorKernel(),
        ["RotorToMatrix"] = () => new RotorToMatrixVectorKernel(),
        ["JuliaStep3"] = () => new JuliaStep3VectorKernel(),
        ["JuliaStep5"] = () => new JuliaStep5VectorKernel(),
        ["RotorInterpolate"] = () => new RotorInterpolateVectorKernel(),
        ["SkewLinesClosestPoints"] = () => new SkewLinesClosestPointsVectorKernel(),
        ["NormalToVectors"] = () => new NormalToVectorsVectorKernel(),
        ["SphereThroughPoints"] = () => new SphereThroughPointsVectorKernel(),
        ["ApplyTwistToPoint3D"] = () => new ApplyTwistToPoint3DVectorKernel(),
        ["SquaredDistance"] = () => new SquaredDistanceVectorKernel(),
        ["RotateAboutAxisThroughPoint3D"] = () => new RotateAboutAxisThroughPoint3DVectorKernel(),
        ["SphereCentreAndRadiusThroughPoints"] = () => new SphereCentreAndRadiusThroughPointsVectorKernel(),
        ["LineThroughPoints"] = () => new LineThroughPointsVectorKernel(),
        ["CircleThroughPoints"] = () => new CircleThroughPointsVectorKernel(),
        ["InverseKinematics"] = () => new InverseKinematicsVectorKernel(),
    };

    /// <summary>One per kernel of <see cref="KernelCatalog"/>, in its order; a kernel without a vector form is an error.</summary>
    public static IReadOnlyList<VectorKernel> CreateAll() =>
        KernelCatalog.Names.Select(name => Factories.TryGetValue(name, out var f) ? f() : throw new InvalidOperationException($"no vector kernel for '{name}'")).ToArray();
}
