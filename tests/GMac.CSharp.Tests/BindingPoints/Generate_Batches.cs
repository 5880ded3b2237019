using System.Globalization;
using System.Reflection;
using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// <c>//GMac.Batch("n")</c>: library macros over spans in structure-of-arrays layout, generated in
/// Vector256&lt;double&gt;, Vector512&lt;double&gt;, Vector&lt;double&gt; and Vector128&lt;float&gt;,
/// compiled with Roslyn and run at lengths around the vector width (vector loop and scalar tail):
/// every item equals what the scalar code of the same macro gives for that item alone.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_Batches
{
    /// <summary>Each macro twice: as a batch over columns, and for one item (plain scalar code).</summary>
    private const string Source = """
        using System.Numerics;
        using System.Runtime.Intrinsics;

        namespace Batches;

        public struct V3 { public double[] x, y, z; public V3(double[][] c, int k) => (x, y, z) = (c[k], c[k + 1], c[k + 2]); }
        public struct R4 { public double[] s, xy, yz, zx; public R4(double[][] c, int k) => (s, xy, yz, zx) = (c[k], c[k + 1], c[k + 2], c[k + 3]); }
        public struct P3 { public double x, y, z; public P3(double[] c, int k) => (x, y, z) = (c[k], c[k + 1], c[k + 2]); }
        public struct Q4 { public double s, xy, yz, zx; public Q4(double[] c, int k) => (s, xy, yz, zx) = (c[k], c[k + 1], c[k + 2], c[k + 3]); }

        public static class Kernels
        {
            /// <summary>The same for every item of a batch (broadcast); counts how often the code reads it.</summary>
            public static double Angle { get { AngleReads++; return 0.7; } }

            public static int AngleReads;

            public static int Lanes => Vector256<double>.Count;

            public static void NormalToVectors(double[][] i, double[][] o)
            {
                V3 u = new(i, 0), v = new(i, 3), w = new(o, 0);
                #region GMac : NormalToVectors
                //GMac.Type("Vector256<double>");
                //GMac.Batch("n");
                //GMac.Bind("u", "Vector3D", "u[n]");
                //GMac.Bind("v", "Vector3D", "v[n]");
                //GMac.Bind("w", "Vector3D", "w[n]");
                #endregion
            }

            public static void NormalToVectorsOne(double[] i, double[] o)
            {
                P3 u = new(i, 0), v = new(i, 3), w = default;
                #region GMac : NormalToVectors
                //GMac.Type("double");
                //GMac.Bind("u", "Vector3D", "u");
                //GMac.Bind("v", "Vector3D", "v");
                //GMac.Bind("w", "Vector3D", "w");
                #endregion
                (o[0], o[1], o[2]) = (w.x, w.y, w.z);
            }

            public static void RotorAxisAngle(double[][] i, double[][] o)
            {
                R4 r = new(i, 0);
                V3 axis = new(o, 0);
                var angle = o[3];
                #region GMac : RotorAxisAngle
                //GMac.Type("Vector256<double>");
                //GMac.Batch("n");
                //GMac.Bind("r", "UnitRotor3D", "r[n]");
                //GMac.Bind("axis", "Vector3D", "axis[n]");
                //GMac.Bind("angle.1", "<angle[n]>");
                #endregion
            }

            public static void RotorAxisAngleOne(double[] i, double[] o)
            {
                Q4 r = new(i, 0);
                P3 axis = default;
                #region GMac : RotorAxisAngle
                //GMac.Type("double");
                //GMac.Bind("r", "UnitRotor3D", "r");
                //GMac.Bind("axis", "Vector3D", "axis");
                //GMac.Bind("angle.1", "<o[3]>");
                #endregion
                (o[0], o[1], o[2]) = (axis.x, axis.y, axis.z);
            }

            public static void SquaredDistance(double[][] i, double[][] o)
            {
                V3 p = new(i, 0), q = new(i, 3);
                var d2 = o[0];
                #region GMac : SquaredDistance
                //GMac.Type("Vector256<double>");
                //GMac.Batch("n");
                //GMac.Bind("p", "ConformalPoint3D", "p[n]");
                //GMac.Bind("q", "ConformalPoint3D", "q[n]");
                //GMac.Bind("d2.1", "<d2[n]>");
                #endregion
            }

            public static void SquaredDistanceOne(double[] i, double[] o)
            {
                P3 p = new(i, 0), q = new(i, 3);
                #region GMac : SquaredDistance
                //GMac.Type("double");
                //GMac.Bind("p", "ConformalPoint3D", "p");
                //GMac.Bind("q", "ConformalPoint3D", "q");
                //GMac.Bind("d2.1", "<o[0]>");
                #endregion
            }

            public static void RotateAboutAxisThroughPoint3D(double[][] i, double[][] o)
            {
                V3 axis = new(i, 0), origin = new(i, 3), x = new(i, 6), y = new(o, 0);
                #region GMac : RotateAboutAxisThroughPoint3D
                //GMac.Type("Vector256<double>");
                //GMac.Batch("n");
                //GMac.Bind("axis", "Vector3D", "axis[n]");
                //GMac.Bind("origin", "Vector3D", "origin[n]");
                //GMac.Bind("angle.1", "<Angle>");
                //GMac.Bind("x", "Point3D", "x[n]");
                //GMac.Bind("y", "Point3D", "y[n]");
                #endregion
            }

            public static void RotateAboutAxisThroughPoint3DOne(double[] i, double[] o)
            {
                P3 axis = new(i, 0), origin = new(i, 3), x = new(i, 6), y = default;
                #region GMac : RotateAboutAxisThroughPoint3D
                //GMac.Type("double");
                //GMac.Bind("axis", "Vector3D", "axis");
                //GMac.Bind("origin", "Vector3D", "origin");
                //GMac.Bind("angle.1", "<Angle>");
                //GMac.Bind("x", "Point3D", "x");
                //GMac.Bind("y", "Point3D", "y");
                #endregion
                (o[0], o[1], o[2]) = (y.x, y.y, y.z);
            }
        }
        """;

    /// <summary>Macro, input columns, output columns.</summary>
    private static readonly (string Macro, int Inputs, int Outputs)[] Macros =
    [
        ("NormalToVectors", 6, 3), ("RotorAxisAngle", 4, 4), ("SquaredDistance", 6, 1), ("RotateAboutAxisThroughPoint3D", 9, 3),
    ];

    /// <summary>Namespace, the vector type replacing Vector256&lt;double&gt;, and whether items are floats.</summary>
    private static readonly (string Namespace, string Vector, bool Single)[] Variants =
    [
        ("Batches", "Vector256<double>", false), ("BatchesWide", "Vector512<double>", false), ("BatchesAny", "Vector<double>", false), ("BatchesF", "Vector128<float>", true),
    ];

    private static string Variant(string ns, string vector, bool single)
    {
        var text = Source.Replace("namespace Batches;", $"namespace {ns};", StringComparison.Ordinal)
            .Replace("Vector256<double>", vector, StringComparison.Ordinal);
        return single ? text.Replace("double", "float", StringComparison.Ordinal).Replace("return 0.7;", "return 0.7f;", StringComparison.Ordinal) : text;
    }

    /// <summary>Generated and compiled once for the class: the files are gone after, the code stays loaded.</summary>
    private static readonly Lazy<Assembly> Compiled = new(() =>
    {
        using var temp = new TempFolder();
        var paths = Variants.Select(v => temp.Write($"{v.Namespace}.cs", Variant(v.Namespace, v.Vector, v.Single))).ToArray();
        var (exit, output, err) = Tool.Generate([temp.Path]);
        Assert.True(exit == 0, err + output);
        return CSharpCompile.Load(paths);
    });

    private static Assembly GenerateAndLoad() => Compiled.Value;

    [Fact]
    public void Every_item_of_a_batch_equals_the_scalar_code_at_lengths_around_the_vector_width()
    {
        var assembly = GenerateAndLoad();
        var random = new Random(26);
        var failures = new List<string>();
        var compared = 0;
        foreach (var (ns, vector, single) in Variants)
        {
            var type = assembly.GetType($"{ns}.Kernels")!;
            var lanes = (int)type.GetProperty("Lanes")!.GetValue(null)!;
            Assert.True(lanes >= 2, $"{vector}: {lanes} lanes");
            foreach (var (macro, inputs, outputs) in Macros)
            {
                var batch = type.GetMethod(macro)!;
                var one = type.GetMethod(macro + "One")!;
                foreach (var length in new[] { 0, 1, lanes - 1, lanes, lanes + 1, 5 * lanes + 3 })
                {
                    var input = Columns(inputs, length, single, () => random.NextDouble() * 3 - 1.5);
                    var output = Columns(outputs, length, single, () => double.NaN);
                    batch.Invoke(null, [input, output]);
                    for (var item = 0; item < length; item++)
                    {
                        var itemInput = Item(input, item, single);
                        var expected = single ? (Array)new float[outputs] : new double[outputs];
                        one.Invoke(null, [itemInput, expected]);
                        compared++;
                        for (var j = 0; j < outputs; j++)
                        {
                            var (a, e) = (Convert.ToDouble(output[j].GetValue(item), CultureInfo.InvariantCulture), Convert.ToDouble(expected.GetValue(j), CultureInfo.InvariantCulture));
                            // The vector sine and cosine are .NET's own approximations, not Math's: a few ulps apart.
                            if (!(Math.Abs(a - e) <= (single ? 2e-6 : 1e-14) * Math.Max(1, Math.Abs(e))))
                                failures.Add(string.Create(CultureInfo.InvariantCulture, $"{macro} {vector} length {length} item {item} output {j}: {a:R}, scalar code {e:R}"));
                        }
                    }
                }
            }
        }
        Assert.True(failures.Count == 0, string.Join("\n", failures.Take(20)));
        Assert.True(compared > 300, $"only {compared} items compared");
    }

    [Fact]
    public void What_reads_no_span_is_computed_once_per_batch_not_once_per_item()
    {
        var assembly = GenerateAndLoad();
        foreach (var (ns, _, single) in Variants)
        {
            var type = assembly.GetType($"{ns}.Kernels")!;
            var lanes = (int)type.GetProperty("Lanes")!.GetValue(null)!;
            var reads = type.GetField("AngleReads")!;
            int ReadsAt(int length)
            {
                reads.SetValue(null, 0);
                type.GetMethod("RotateAboutAxisThroughPoint3D")!.Invoke(null, [Columns(9, length, single, () => 0.5), Columns(3, length, single, () => 0)]);
                return (int)reads.GetValue(null)!;
            }
            var once = ReadsAt(1);
            Assert.True(once > 0);
            Assert.Equal(once, ReadsAt(lanes - 1));
            Assert.Equal(once, ReadsAt(7 * lanes + 3));
        }
    }

    [Fact]
    public void Spans_of_different_lengths_are_an_argument_exception_before_anything_is_written()
    {
        var type = GenerateAndLoad().GetType("Batches.Kernels")!;
        var input = Columns(6, 9, false, () => 1);
        input[4] = new double[8];
        var output = Columns(3, 9, false, () => double.NaN);
        var thrown = Assert.Throws<TargetInvocationException>(() => type.GetMethod("NormalToVectors")!.Invoke(null, [input, output]));
        var argument = Assert.IsType<ArgumentException>(thrown.InnerException);
        Assert.Contains("NormalToVectors", argument.Message);
        Assert.All(output, column => Assert.All((double[])column, x => Assert.True(double.IsNaN(x))));
    }

    /// <summary><paramref name="count"/> columns of <paramref name="length"/> items: a double[][] or a float[][].</summary>
    private static Array[] Columns(int count, int length, bool single, Func<double> value)
    {
        Array[] columns = single ? new float[count][] : new double[count][];
        for (var c = 0; c < count; c++)
        {
            columns[c] = single ? new float[length] : new double[length];
            for (var k = 0; k < length; k++) columns[c].SetValue(single ? (object)(float)value() : value(), k);
        }
        return columns;
    }

    private static Array Item(Array[] columns, int item, bool single)
    {
        Array values = single ? new float[columns.Length] : new double[columns.Length];
        for (var k = 0; k < columns.Length; k++) values.SetValue(columns[k].GetValue(item), k);
        return values;
    }
}
