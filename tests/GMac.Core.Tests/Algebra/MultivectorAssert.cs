using GMac.Core.Algebra;

namespace GMac.Core.Tests.Algebra;

internal static class MultivectorAssert
{
    public static void Close(Multivector<double> expected, Multivector<double> actual, double tolerance = 1e-9)
    {
        Assert.Same(expected.Frame, actual.Frame);
        var scale = Math.Max(1, expected.Terms.Select(t => Math.Abs(t.Coefficient)).DefaultIfEmpty(0).Max());
        for (var id = 0; id < expected.Frame.BladeCount; id++)
        {
            var b = new BasisBlade(id);
            var e = expected[b];
            var a = actual[b];
            if (Math.Abs(e - a) > tolerance * scale)
                Assert.Fail($"Coefficient of {expected.Frame.BladeName(b)}: expected {e}, got {a}.\nexpected: {expected}\nactual:   {actual}");
        }
    }

    public static void Close(double expected, double actual, double tolerance = 1e-9)
    {
        if (Math.Abs(expected - actual) > tolerance * Math.Max(1, Math.Abs(expected)))
            Assert.Fail($"Expected {expected}, got {actual}.");
    }
}
