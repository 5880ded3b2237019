namespace GMac.Benchmarks.Kernels;

/// <summary>The kernels of the suite, in the order of the report.</summary>
public static class KernelCatalog
{
    private static readonly Func<IGaKernel>[] Factories =
    [
        () => new HiddenSurfaceKernel(),
        () => new VortexSKernel(),
        () => new Circ3Kernel(),
        () => new GramSchmidtContractionKernel(),
        () => new GramSchmidtRejectionKernel(),
        () => new RotorToMatrixKernel(),
        () => new JuliaStep3Kernel(),
        () => new JuliaStep5Kernel(),
        () => new RotorInterpolateKernel(),
        () => new SkewLinesClosestPointsKernel(),
        () => new NormalToVectorsKernel(),
        () => new SphereThroughPointsKernel(),
        () => new ApplyTwistToPoint3DKernel(),
        () => new SquaredDistanceKernel(),
        () => new RotateAboutAxisThroughPoint3DKernel(),
        () => new SphereCentreAndRadiusThroughPointsKernel(),
        () => new LineThroughPointsKernel(),
        () => new CircleThroughPointsKernel(),
        () => new InverseKinematicsKernel(),
    ];

    public static IReadOnlyList<string> Names { get; } = Factories.Select(f => f().MacroName).ToArray();

    public static IReadOnlyList<IGaKernel> CreateAll() => Factories.Select(f => f()).ToArray();

    public static IGaKernel Create(string macroName) =>
        Factories.Select(f => f()).FirstOrDefault(k => k.MacroName == macroName)
        ?? throw new ArgumentException($"no kernel for macro '{macroName}'; known: {string.Join(", ", Names)}", nameof(macroName));
}
