using System.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// A fixed symbolic workload: the Euclidean geometric product of two general
/// multivectors of an n-dimensional space with symbolic coefficients a0…, b0…, accumulated
/// coefficient by coefficient as a generic multivector product does. Independent of the algebra
/// layer on purpose, so it exercises the scalar engine alone.
/// </summary>
internal sealed class GeometricProductWorkload
{
    private readonly Scalar[] _left;
    private readonly Scalar[] _right;

    /// <param name="dimension">n, giving 2^n coefficients per multivector.</param>
    /// <param name="leftName">Prefix of the left coefficient names; fresh prefixes give a run with nothing interned yet.</param>
    /// <param name="rightName">Prefix of the right coefficient names.</param>
    public GeometricProductWorkload(int dimension, string leftName = "a", string rightName = "b")
    {
        if (dimension is < 0 or > 10)
            throw new ArgumentOutOfRangeException(nameof(dimension), dimension, "Use a dimension from 0 to 10.");
        Dimension = dimension;
        var size = 1 << dimension;
        _left = new Scalar[size];
        _right = new Scalar[size];
        for (var i = 0; i < size; i++)
        {
            _left[i] = Scalar.Variable($"{leftName}{i}");
            _right[i] = Scalar.Variable($"{rightName}{i}");
        }
    }

    public int Dimension { get; }

    public IReadOnlyList<Scalar> Left => _left;

    public IReadOnlyList<Scalar> Right => _right;

    /// <summary>The 2^n coefficients of the product, indexed by basis-blade bitmap.</summary>
    public Scalar[] Run()
    {
        var size = _left.Length;
        var result = new Scalar[size];
        Array.Fill(result, Scalar.Zero);
        for (var i = 0; i < size; i++)
        for (var j = 0; j < size; j++)
        {
            var product = _left[i] * _right[j];
            result[i ^ j] = ReorderingSign(i, j) > 0 ? result[i ^ j] + product : result[i ^ j] - product;
        }
        return result;
    }

    /// <summary>The same product accumulated with <see cref="ScalarSumBuilder"/> (no partial sums interned).</summary>
    public Scalar[] RunWithSumBuilder()
    {
        var size = _left.Length;
        var result = new Scalar[size];
        var builder = new ScalarSumBuilder();
        for (var k = 0; k < size; k++)
        {
            builder.Clear();
            for (var i = 0; i < size; i++)
                builder.AddProduct(_left[i], _right[i ^ k], ReorderingSign(i, i ^ k));
            result[k] = builder.ToScalar();
        }
        return result;
    }

    /// <summary>The same product on numbers, as a reference.</summary>
    public static double[] Run(double[] left, double[] right)
    {
        ArgumentNullException.ThrowIfNull(left);
        ArgumentNullException.ThrowIfNull(right);
        if (left.Length != right.Length || !BitOperations.IsPow2(left.Length))
            throw new ArgumentException("Both multivectors need the same power-of-two number of coefficients.", nameof(right));
        var result = new double[left.Length];
        for (var i = 0; i < left.Length; i++)
        for (var j = 0; j < right.Length; j++)
            result[i ^ j] += ReorderingSign(i, j) * left[i] * right[j];
        return result;
    }

    /// <summary>Sign of e_A e_B = ±e_(A xor B) for orthonormal Euclidean basis blades given as bitmaps.</summary>
    public static int ReorderingSign(int a, int b)
    {
        var swaps = 0;
        for (a >>= 1; a != 0; a >>= 1) swaps += BitOperations.PopCount((uint)(a & b));
        return (swaps & 1) == 0 ? 1 : -1;
    }
}
