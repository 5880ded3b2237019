using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Values;

namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// The input families of each kernel: its own random inputs, then ill-conditioned ones built from
/// them (a large common offset, where the inputs are positions; a nearly degenerate configuration).
/// A kernel not listed here is measured on its random inputs alone.
/// </summary>
public static class AccuracyFamilies
{
    public const double Offset = 1e5;

    /// <summary>The part that the vectors of the Gram–Schmidt family "common-part" share.</summary>
    public const double CommonPart = 1e4;

    public static IReadOnlyList<InputFamily> For(IGaKernel kernel)
    {
        var subject = kernel as IAccuracySubject
            ?? throw new InvalidOperationException($"{kernel.MacroName}: the kernel does not expose its inputs (derive it from GaKernel)");
        var families = new List<InputFamily> { new("random", "the benchmark's random inputs", subject.RandomInput) };
        families.AddRange(kernel.MacroName switch
        {
            "HiddenSurface" =>
            [
                From<Vec2Triple>(subject, "offset", "triangle moved by (1e5, 1e5)", (t, _) => new() { A = Add(t.A, Offset), B = Add(t.B, Offset), C = Add(t.C, Offset) }),
                From<Vec2Triple>(subject, "near-collinear", "third vertex 1e-9 off the line of the other two", (t, r) =>
                    t with { C = new((t.A.x + t.B.x) / 2 + 1e-9 * Signed(r), (t.A.y + t.B.y) / 2 + 1e-9 * Signed(r)) }),
            ],
            "Circ3" => [From<Vec3>(subject, "large", "coordinates near 1e4", (p, _) => Scale(p, 1e4))],
            "GramSchmidtContraction" =>
            [
                From<Vec3Triple>(subject, "near-dependent", "third vector 1e-7 off the plane of the first two", (v, r) =>
                    v with { C = Add(Add(Scale(v.A, 0.5), Scale(v.B, 0.5)), Scale(RandomVec(r), 1e-7)) }),
            ],
            "GramSchmidtRejection" =>
            [
                From<Vec3Triple>(subject, "near-dependent", "third vector 1e-7 off the plane of the first two", (v, r) =>
                    v with { C = Add(Add(Scale(v.A, 0.5), Scale(v.B, 0.5)), Scale(RandomVec(r), 1e-7)) }),
                // nearly parallel vectors whose third lies close to the plane of the first two: the
                // textbook w3 from v1 × v2 loses digits here that w3 from w1 ∧ w2 keeps
                From<Vec3Triple>(subject, "common-part", "the three vectors plus (1e4, 1e4, 1e4)", (v, _) =>
                    new() { A = Add(v.A, CommonPart), B = Add(v.B, CommonPart), C = Add(v.C, CommonPart) }),
            ],
            "RotorToMatrix" => [From<Rotor3>(subject, "near-identity", "rotation by about 1e-6 rad", (_, r) => Unit(new Rotor3(1, 1e-6 * Signed(r), 1e-6 * Signed(r), 1e-6 * Signed(r))))],
            "JuliaStep3" or "JuliaStep5" => [From<Vec2Pair>(subject, "large", "point of size 1e3", (j, _) => j with { X = new(j.X.x * 1e3, j.X.y * 1e3) })],
            "RotorInterpolate" =>
            [
                From<RotorPair>(subject, "close", "rotors 1e-4 apart", (p, r) =>
                    p with { R2 = Unit(new Rotor3(p.R1.w + 1e-4 * Signed(r), p.R1.x + 1e-4 * Signed(r), p.R1.y + 1e-4 * Signed(r), p.R1.z + 1e-4 * Signed(r))) }),
            ],
            "SkewLinesClosestPoints" =>
            [
                From<LinePair>(subject, "offset", "lines moved by 1e5 along each axis", (l, _) => l with { P1 = Add(l.P1, Offset), P2 = Add(l.P2, Offset) }),
                From<LinePair>(subject, "near-parallel", "directions 1e-6 apart", (l, r) => l with { D2 = Add(l.D1, Scale(RandomVec(r), 1e-6)) }),
            ],
            "NormalToVectors" => [From<Vec3Pair>(subject, "near-parallel", "vectors 1e-8 apart", (x, r) => x with { V = Add(x.U, Scale(RandomVec(r), 1e-8)) })],
            "SphereThroughPoints" or "SphereCentreAndRadiusThroughPoints" =>
            [
                From<Vec3Quad>(subject, "offset", "sphere moved by 1e5 along each axis", (q, _) => new() { P1 = Add(q.P1, Offset), P2 = Add(q.P2, Offset), P3 = Add(q.P3, Offset), P4 = Add(q.P4, Offset) }),
                From<Vec3Quad>(subject, "near-coplanar", "fourth point 1e-6 off the plane of the others", (q, r) =>
                    q with { P4 = Add(Scale(Add(Add(q.P1, q.P2), q.P3), 1.0 / 3), Scale(RandomVec(r), 1e-6)) }),
            ],
            "ApplyTwistToPoint3D" =>
            [
                From<TwistInput>(subject, "offset", "axis and point moved by 1e5 along each axis", (x, _) => x with { Origin = Add(x.Origin, Offset), Point = Add(x.Point, Offset) }),
                From<TwistInput>(subject, "small-angle", "angle and slide near 1e-8", (x, _) => x with { Angle = x.Angle * 1e-8, Slide = x.Slide * 1e-8 }),
            ],
            "SquaredDistance" =>
            [
                From<Vec3Pair>(subject, "close-far", "points near 1e4, 1e-3 apart", (x, r) =>
                {
                    var a = Add(x.U, 1e4);
                    return new Vec3Pair { U = a, V = Add(a, Scale(RandomVec(r), 1e-3)) };
                }),
                From<Vec3Pair>(subject, "offset", "points moved by 1e5 along each axis", (x, _) => new Vec3Pair { U = Add(x.U, Offset), V = Add(x.V, Offset) }),
            ],
            "LineThroughPoints" =>
            [
                From<Vec3Pair>(subject, "close-far", "points near 1e5, 1e-3 apart", (x, r) =>
                {
                    var a = Add(x.U, Offset);
                    return new Vec3Pair { U = a, V = Add(a, Scale(RandomVec(r), 1e-3)) };
                }),
            ],
            "CircleThroughPoints" =>
            [
                From<Vec3Triple>(subject, "close-far", "points near 1e5, 1e-3 apart", (x, r) =>
                {
                    var a = Add(x.A, Offset);
                    return new Vec3Triple { A = a, B = Add(a, Scale(RandomVec(r), 1e-3)), C = Add(a, Scale(RandomVec(r), 1e-3)) };
                }),
            ],
            _ => [],
        });
        return families;
    }

    private static InputFamily From<T>(IAccuracySubject subject, string name, string description, Func<T, Random, T> derive) where T : struct =>
        new(name, description, random => derive((T)subject.RandomInput(random), random));

    private static double Signed(Random random) => random.NextDouble() * 2 - 1;

    private static Vec3 RandomVec(Random random) => new(Signed(random), Signed(random), Signed(random));

    private static Vec2 Add(Vec2 v, double d) => new(v.x + d, v.y + d);

    private static Vec3 Add(Vec3 v, double d) => new(v.x + d, v.y + d, v.z + d);

    private static Vec3 Add(Vec3 a, Vec3 b) => new(a.x + b.x, a.y + b.y, a.z + b.z);

    private static Vec3 Scale(Vec3 v, double s) => new(v.x * s, v.y * s, v.z * s);

    private static Rotor3 Unit(Rotor3 r)
    {
        var n = Math.Sqrt(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
        return new Rotor3(r.w / n, r.x / n, r.y / n, r.z / n);
    }
}
