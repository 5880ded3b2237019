using System.Text.RegularExpressions;
using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// Structure-of-arrays packets: structs whose members are Vector256&lt;double&gt;, bound through the
/// library's class bindings unchanged, in regions with <c>//GMac.Type("Vector256&lt;double&gt;")</c>.
/// The file generates, compiles with Roslyn, runs right in every lane, and gmac verify passes it.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed partial class Generate_VectorPackets : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string Source = """
        using System.Runtime.Intrinsics;

        namespace Packets;

        /// <summary>Four 3D vectors, one per lane.</summary>
        public struct Vec3x4 { public Vector256<double> x, y, z; }

        /// <summary>Four unit rotors, one per lane.</summary>
        public struct Rotor3x4 { public Vector256<double> s, xy, yz, zx; }

        public static class Kernels
        {
            public static Vec3x4 Normal(Vec3x4 u, Vec3x4 v)
            {
                var w = new Vec3x4();
                #region GMac : NormalToVectors
                //GMac.Type("Vector256<double>");
                //GMac.Bind("u", "Vector3D", u);
                //GMac.Bind("v", "Vector3D", v);
                //GMac.Bind("w", "Vector3D", w);
                #endregion
                return w;
            }

            public static (Vec3x4 Axis, Vector256<double> Angle) AxisAngle(Rotor3x4 r)
            {
                var axis = new Vec3x4();
                Vector256<double> angle;
                #region GMac : RotorAxisAngle
                //GMac.Type("Vector256<double>");
                //GMac.Bind("r", "UnitRotor3D", r);
                //GMac.Bind("axis", "Vector3D", axis);
                //GMac.Bind("angle.1", "<angle>");
                #endregion
                return (axis, angle);
            }

            // Lanes in and out through arrays, for the test: x0..x3, y0..y3, z0..z3.
            private static Vec3x4 Vec(double[] a) => new() { x = Vector256.Create(a, 0), y = Vector256.Create(a, 4), z = Vector256.Create(a, 8) };

            private static double[] Lanes(params Vector256<double>[] vectors)
            {
                var lanes = new double[4 * vectors.Length];
                for (var k = 0; k < vectors.Length; k++) vectors[k].CopyTo(lanes, 4 * k);
                return lanes;
            }

            public static double[] NormalLanes(double[] u, double[] v)
            {
                var w = Normal(Vec(u), Vec(v));
                return Lanes(w.x, w.y, w.z);
            }

            public static double[] AxisAngleLanes(double[] r)
            {
                var (axis, angle) = AxisAngle(new Rotor3x4 { s = Vector256.Create(r, 0), xy = Vector256.Create(r, 4), yz = Vector256.Create(r, 8), zx = Vector256.Create(r, 12) });
                return Lanes(axis.x, axis.y, axis.z, angle);
            }
        }
        """;

    private string GenerateFile()
    {
        var path = _temp.Write("Packets/Kernels.cs", Source);
        var (exit, output, err) = Tool.Generate([_temp.Path]);
        Assert.True(exit == 0, err + output);
        return path;
    }

    [Fact]
    public void Vector_members_of_class_bindings_become_vector_code()
    {
        var text = File.ReadAllText(GenerateFile());
        Assert.Contains("w.x = u.y * v.z - u.z * v.y;", text);
        // The angle's 2 is broadcast once; atan2 has no vector form and runs per lane.
        Assert.Single(Regex.Matches(text, @"Vector256\.Create\(2\.0\)"));
        Assert.Contains("Math.Atan2(", text);
        Assert.Contains("Vector256.Sqrt(", text);
        Assert.DoesNotMatch(@"\bdouble \w+ =", text);
    }

    [Fact]
    public void The_generated_file_compiles_and_every_lane_is_the_scalar_formula_of_its_own_inputs()
    {
        var type = CSharpCompile.Load(GenerateFile()).GetType("Packets.Kernels")!;
        var random = new Random(4);
        var u = Enumerable.Range(0, 12).Select(_ => random.NextDouble() * 2 - 1).ToArray();
        var v = Enumerable.Range(0, 12).Select(_ => random.NextDouble() * 2 - 1).ToArray();
        var w = (double[])type.GetMethod("NormalLanes")!.Invoke(null, [u, v])!;
        for (var l = 0; l < 4; l++)
        {
            Assert.Equal(u[4 + l] * v[8 + l] - u[8 + l] * v[4 + l], w[l]);
            Assert.Equal(u[8 + l] * v[l] - u[l] * v[8 + l], w[4 + l]);
            Assert.Equal(u[l] * v[4 + l] - u[4 + l] * v[l], w[8 + l]);
        }

        // Unit rotors cos(φ/2) − sin(φ/2) P about random axes by random angles in (0, 2π).
        var r = new double[16];
        var angles = new double[4];
        for (var l = 0; l < 4; l++)
        {
            angles[l] = 0.1 + random.NextDouble() * 6;
            var axis = Enumerable.Range(0, 3).Select(_ => random.NextDouble() * 2 - 1).ToArray();
            var norm = Math.Sqrt(axis.Sum(a => a * a));
            var (sin, cos) = Math.SinCos(angles[l] / 2);
            // P = axis ⌋ I3: e1 → e2^e3 (yz), e2 → e3^e1 (zx), e3 → e1^e2 (xy).
            (r[l], r[4 + l], r[8 + l], r[12 + l]) = (cos, -sin * axis[2] / norm, -sin * axis[0] / norm, -sin * axis[1] / norm);
        }
        var result = (double[])type.GetMethod("AxisAngleLanes")!.Invoke(null, [r])!;
        for (var l = 0; l < 4; l++)
        {
            var sinHalf = Math.Sqrt(r[4 + l] * r[4 + l] + r[8 + l] * r[8 + l] + r[12 + l] * r[12 + l]);
            Assert.Equal(2 * Math.Atan2(sinHalf, r[l]), result[12 + l]);
            Assert.Equal(angles[l], result[12 + l], 1e-12);
            Assert.Equal(1.0, Math.Sqrt(result[l] * result[l] + result[4 + l] * result[4 + l] + result[8 + l] * result[8 + l]), 1e-12);
        }
    }

    [Fact]
    public void Gmac_verify_compares_every_lane_of_vector_regions_with_the_engine()
    {
        GenerateFile();
        var (exit, output, err) = Tool.Verify(_temp.Path);
        Assert.True(exit == 0, err + output);
        Assert.Contains("gmac verify: 2 region(s), 2 passed, 0 problem(s)", output);
        // Five samples asked for: two whole vectors of four lanes.
        Assert.Contains("ok NormalToVectors: 3 output(s), 8 samples", output);
    }
}
