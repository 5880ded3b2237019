using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>
/// A kernel of the suite over its batch in columns: the inputs of its scalar kernel (same seed, same
/// items) copied into one array per double, and one array per output coefficient (each 64-byte aligned, see
/// <see cref="AlignedColumns"/>), in the order the
/// scalar kernel lists its outputs. The scalar kernel's generated code is the reference and the baseline.
/// </summary>
public abstract class VectorKernel(IGaKernel scalar)
{
    private double[][] _inputs = [];
    private readonly Dictionary<VectorVariant, double[][]> _outputs = [];
    private double[][] _timed = [];

    public IGaKernel Scalar { get; } = scalar;

    public string MacroName => Scalar.MacroName;

    public int Count => Scalar.Count;

    /// <summary>Input and output columns together (after <see cref="Setup"/>): the doubles a batch reads and writes per item.</summary>
    public int ColumnCount => _inputs.Length + _timed.Length;

    /// <summary>Whether this kernel has vector code written by hand.</summary>
    public virtual bool HasHand => false;

    /// <summary>Whether the variant can be timed here: it exists, and Vector512 runs on hardware.</summary>
    public bool Supports(VectorVariant variant) => variant switch
    {
        VectorVariant.Generated512 => Vector512.IsHardwareAccelerated,
        VectorVariant.Hand256 => HasHand,
        _ => true,
    };

    public void Setup(int count, int seed)
    {
        Scalar.Setup(count, seed);
        Scalar.Run(Variant.Generated);
        var inputs = Scalar.InputDoubles(0).Count;
        var outputs = Scalar.Output(Variant.Generated, 0).Count;
        _inputs = Columns(inputs, count);
        for (var k = 0; k < count; k++)
        {
            var item = Scalar.InputDoubles(k);
            for (var c = 0; c < inputs; c++) _inputs[c][k] = item[c];
        }
        foreach (var v in Enum.GetValues<VectorVariant>()) _outputs[v] = Columns(outputs, count);
        _timed = Columns(outputs, count);
    }

    public void Run(VectorVariant variant) => Run(variant, _outputs[variant]);

    /// <summary>Runs a variant into the output columns every timed variant shares.</summary>
    public void Time(VectorVariant variant) => Run(variant, _timed);

    public IReadOnlyList<double> Output(VectorVariant variant, int index) => _outputs[variant].Select(column => column[index]).ToArray();

    private void Run(VectorVariant variant, double[][] outputs)
    {
        switch (variant)
        {
            case VectorVariant.Generated256: Generated256(_inputs, outputs); break;
            case VectorVariant.Generated512: Generated512(_inputs, outputs); break;
            case VectorVariant.Hand256 when HasHand: Hand256(_inputs, outputs); break;
            default: throw new ArgumentOutOfRangeException(nameof(variant), $"{MacroName} has no {variant} code");
        }
    }

    private static double[][] Columns(int count, int length) => AlignedColumns.Allocate(count, length);

    protected abstract void Generated256(double[][] i, double[][] o);

    protected abstract void Generated512(double[][] i, double[][] o);

    protected virtual void Hand256(double[][] i, double[][] o) => throw new NotSupportedException();

    /// <summary>
    /// The items of hand-written code go four at a time: 0, 4, 8, … and, for a length not a multiple
    /// of four, a last step that ends at the last item (it recomputes up to three items, writing the same values).
    /// </summary>
    protected static int ItemsInSteps(double[] column)
    {
        if (column.Length < 4) throw new ArgumentException($"the hand-written vector code takes batches of at least 4 items, not {column.Length}", nameof(column));
        return column.Length;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    protected static Vector256<double> Load(double[] column, int k) => Vector256.LoadUnsafe(ref MemoryMarshal.GetArrayDataReference(column), (nuint)k);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    protected static void Store(Vector256<double> value, double[] column, int k) => value.StoreUnsafe(ref MemoryMarshal.GetArrayDataReference(column), (nuint)k);
}
