using System.Numerics;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Values;

namespace GMac.Benchmarks.Tests.Kernels;

/// <summary>The generated kernels against closed forms and geometric invariants, independent of the other two variants.</summary>
public class GeneratedKernels_AnalyticValues
{
    private const double Eps = 1e-12;

    private static double Dot(Vec3 a, Vec3 b) => a.x * b.x + a.y * b.y + a.z * b.z;

    private static Vec3 Sub(Vec3 a, Vec3 b) => new(a.x - b.x, a.y - b.y, a.z - b.z);

    private static Vec3 Add(Vec3 a, Vec3 b, double t) => new(a.x + t * b.x, a.y + t * b.y, a.z + t * b.z);

    [Fact]
    public void Hidden_surface_gives_minus_one_for_the_unit_triangle_with_v2_on_e1()
    {
        var t = new Vec2Triple { A = new(0, 0), B = new(1, 0), C = new(0, 1) };
        HiddenSurfaceKernel.Generated(in t, out var s);
        Assert.Equal(-1, s, Eps);
    }

    [Fact]
    public void Vortex_s_of_p_perpendicular_to_a_is_gamma_times_the_third_axis()
    {
        var x = new VortexInput { P = new(0, 1, 0), A = new(1, 0, 0), Omega = 5, Gamma = 3 };
        VortexSKernel.Generated(in x, out var v);
        Assert.Equal(0, v.x, Eps);
        Assert.Equal(0, v.y, Eps);
        Assert.Equal(3, v.z, Eps);
    }

    [Fact]
    public void Circ3_at_one_one_one_is_four_four_two()
    {
        Circ3Kernel.Generated(new Vec3(1, 1, 1), out var v);
        Assert.Equal(4, v.x, Eps);
        Assert.Equal(4, v.y, Eps);
        Assert.Equal(2, v.z, Eps);
    }

    [Fact]
    public void Normal_of_e1_and_e2_is_e3()
    {
        NormalToVectorsKernel.Generated(new Vec3Pair { U = new(1, 0, 0), V = new(0, 1, 0) }, out var w);
        Assert.Equal(0, w.x, Eps);
        Assert.Equal(0, w.y, Eps);
        Assert.Equal(1, w.z, Eps);
    }

    [Fact]
    public void Both_gram_schmidt_forms_give_mutually_orthogonal_vectors_spanning_the_same_flags()
    {
        var v = new Vec3Triple { A = new(2, 0.3, -0.4), B = new(0.5, 1.7, 0.2), C = new(-0.3, 0.6, 1.9) };
        GramSchmidtContractionKernel.Generated(in v, out var c);
        GramSchmidtRejectionKernel.Generated(in v, out var r);
        foreach (var w in new[] { c, r })
        {
            Assert.Equal(0, Dot(w.A, w.B), 1e-12);
            Assert.Equal(0, Dot(w.A, w.C), 1e-12);
            Assert.Equal(0, Dot(w.B, w.C), 1e-12);
            // w2 lies in the plane of v1, v2: det(v1, v2, w2) = 0.
            var n = new Vec3(v.A.y * v.B.z - v.A.z * v.B.y, v.A.z * v.B.x - v.A.x * v.B.z, v.A.x * v.B.y - v.A.y * v.B.x);
            Assert.Equal(0, Dot(n, w.B), 1e-12);
        }
        // The rejection form keeps v1's length on w1 and v3's component along the normal on w3.
        Assert.Equal(Dot(v.A, v.A), Dot(r.A, r.A), 1e-12);
    }

    [Fact]
    public void Rotor_matrix_is_orthonormal_right_handed_and_fixes_the_rotation_axis()
    {
        var (w, x, y, z) = (0.8, 0.2, -0.4, 0.4);
        var n = Math.Sqrt(w * w + x * x + y * y + z * z);
        var q = new Rotor3(w / n, x / n, y / n, z / n);
        RotorToMatrixKernel.Generated(in q, out var m);
        Assert.Equal(1, Dot(m.A, m.A), 1e-12);
        Assert.Equal(1, Dot(m.B, m.B), 1e-12);
        Assert.Equal(0, Dot(m.A, m.B), 1e-12);
        Assert.Equal(0, Dot(m.A, m.C), 1e-12);
        var det = m.A.x * (m.B.y * m.C.z - m.B.z * m.C.y) - m.A.y * (m.B.x * m.C.z - m.B.z * m.C.x) + m.A.z * (m.B.x * m.C.y - m.B.y * m.C.x);
        Assert.Equal(1, det, 1e-12);
        // M axis = axis for the axis (x, y, z) of R = w + x e23 + y e31 + z e12; the columns are m.A, m.B, m.C.
        var axis = new Vec3(q.x, q.y, q.z);
        var image = new Vec3(
            m.A.x * axis.x + m.B.x * axis.y + m.C.x * axis.z,
            m.A.y * axis.x + m.B.y * axis.y + m.C.y * axis.z,
            m.A.z * axis.x + m.B.z * axis.y + m.C.z * axis.z);
        Assert.Equal(axis.x, image.x, 1e-12);
        Assert.Equal(axis.y, image.y, 1e-12);
        Assert.Equal(axis.z, image.z, 1e-12);
    }

    [Theory]
    [InlineData(0.3, -0.7, 0.1, 0.2)]
    [InlineData(-1.1, 0.4, -0.5, 0.9)]
    public void Julia_steps_are_the_complex_powers_plus_c(double a, double b, double ca, double cb)
    {
        var j = new Vec2Pair { X = new(a, b), C = new(ca, cb) };
        var z = new Complex(a, b);
        var c = new Complex(ca, cb);
        JuliaStep3Kernel.Generated(in j, out var y3);
        JuliaStep5Kernel.Generated(in j, out var y5);
        var z3 = z * z * z + c;
        var z5 = z * z * z * z * z + c;
        Assert.Equal(z3.Real, y3.x, 1e-12);
        Assert.Equal(z3.Imaginary, y3.y, 1e-12);
        Assert.Equal(z5.Real, y5.x, 1e-12);
        Assert.Equal(z5.Imaginary, y5.y, 1e-12);
    }

    [Fact]
    public void Rotor_interpolation_approaches_r1_reaches_r2_and_bisects_at_one_half()
    {
        var r1 = new Rotor3(0.9, 0.3, -0.1, 0.2);
        var r2 = new Rotor3(0.5, -0.2, 0.6, 0.3);
        r1 = Normalize(r1);
        r2 = Normalize(r2);
        // (7.10) divides by φ, so α = 0 itself is singular (0/0); a tiny α must land next to R1.
        foreach (var (alpha, expected) in new[] { (1e-13, r1), (1.0, r2) })
        {
            RotorInterpolateKernel.Generated(new RotorPair { R1 = r1, R2 = r2, Alpha = alpha }, out var r);
            Assert.Equal(expected.w, r.w, 1e-12);
            Assert.Equal(expected.x, r.x, 1e-12);
            Assert.Equal(expected.y, r.y, 1e-12);
            Assert.Equal(expected.z, r.z, 1e-12);
        }
        RotorInterpolateKernel.Generated(new RotorPair { R1 = r1, R2 = r2, Alpha = 0.5 }, out var half);
        Assert.Equal(1, Dot4(half, half), 1e-12);
        Assert.Equal(Dot4(half, r1), Dot4(half, r2), 1e-12);

        static double Dot4(Rotor3 a, Rotor3 b) => a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
        static Rotor3 Normalize(Rotor3 r)
        {
            var n = Math.Sqrt(Dot4(r, r));
            return new Rotor3(r.w / n, r.x / n, r.y / n, r.z / n);
        }
    }

    [Fact]
    public void Closest_points_of_skew_lines_are_joined_perpendicular_to_both_lines()
    {
        var l = new LinePair { P1 = new(0.1, -0.4, 0.3), D1 = new(1.5, 0.2, -0.3), P2 = new(-0.6, 0.8, 1.1), D2 = new(0.1, 1.2, 0.7) };
        SkewLinesClosestPointsKernel.Generated(in l, out var t);
        var joint = Sub(Add(l.P2, l.D2, t.T2), Add(l.P1, l.D1, t.T1));
        Assert.Equal(0, Dot(joint, l.D1), 1e-12);
        Assert.Equal(0, Dot(joint, l.D2), 1e-12);
    }

    [Fact]
    public void Dual_sphere_through_four_points_has_a_centre_equidistant_from_them()
    {
        var q = new Vec3Quad { P1 = new(1, 0.2, 0), P2 = new(-0.3, 1, 0.4), P3 = new(0.1, -0.8, 0.9), P4 = new(0.5, 0.5, -1) };
        SphereThroughPointsKernel.Generated(in q, out var s);
        // ω = α (no + c + ½(c² − r²) ni), so c = ω_E / ω_no and r² = c² − 2 ω_ni / ω_no.
        var c = new Vec3(s.E1 / s.No, s.E2 / s.No, s.E3 / s.No);
        var r2 = Dot(c, c) - 2 * s.Ni / s.No;
        foreach (var p in new[] { q.P1, q.P2, q.P3, q.P4 })
        {
            var d = Sub(p, c);
            Assert.Equal(r2, Dot(d, d), 1e-10);
        }
    }

    [Fact]
    public void Twist_turns_right_handed_about_the_axis_line_and_slides_by_the_parameter_times_the_axis()
    {
        var x = new TwistInput { Axis = new(0, 0, 2), Origin = new(1, 1, 0), Angle = Math.PI / 2, Slide = 0.25, Point = new(2, 1, 0.5) };
        ApplyTwistToPoint3DKernel.Generated(in x, out var p);
        // A right-handed quarter turn of the offset (1, 0, ·) about the vertical line through (1, 1), then up by 0.25 · 2.
        Assert.Equal(1, p.x, 1e-12);
        Assert.Equal(2, p.y, 1e-12);
        Assert.Equal(1, p.z, 1e-12);
    }
}
