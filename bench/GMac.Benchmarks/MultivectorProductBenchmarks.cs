using BenchmarkDotNet.Attributes;
using GMac.Core.Algebra;
using GMac.Core.Symbolic;

namespace GMac.Benchmarks;

/// <summary>
/// The geometric product of two general multivectors of the 5D conformal frame (32 blades each):
/// with symbolic coefficients (what code generation does) and with doubles (the direct baseline).
/// </summary>
[MemoryDiagnoser]
public class MultivectorProductBenchmarks
{
    private readonly Frame _frame = Frame.Conformal3D();
    private readonly Frame _orthogonal = Frame.FromSignature("cl41", 4, 1);
    private Multivector<double> _a = null!, _b = null!, _orthoA = null!, _orthoB = null!;
    private Multivector<Scalar> _sa = null!, _sb = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(42);
        Multivector<double> General() => Multivector<double>.FromTerms(_frame,
            Enumerable.Range(0, _frame.BladeCount).Select(id => (new BasisBlade(id), random.NextDouble() * 2 - 1)));
        _a = General();
        _b = General();
        _sa = SymbolicMultivector.Variables(_frame, "a");
        _sb = SymbolicMultivector.Variables(_frame, "b");
        _orthoA = Multivector<double>.FromTerms(_orthogonal, _a.Terms);
        _orthoB = Multivector<double>.FromTerms(_orthogonal, _b.Terms);
        // Warm the product tables so the benchmark measures products, not table construction.
        _ = _a.Gp(_b);
        _ = _sa.Gp(_sb);
        _ = _orthoA.Gp(_orthoB);
    }

    [Benchmark(Description = "symbolic gp, cga5d general x general")]
    public Multivector<Scalar> SymbolicGeometricProduct() => _sa.Gp(_sb);

    [Benchmark(Description = "numeric gp, cga5d general x general")]
    public Multivector<double> NumericGeometricProduct() => _a.Gp(_b);

    [Benchmark(Description = "numeric gp, Cl(4,1) general x general")]
    public Multivector<double> NumericGeometricProductOrthogonal() => _orthoA.Gp(_orthoB);

}
