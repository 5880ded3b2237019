using RayTracer.Geometry.Solvers;
using RayTracer.Randomness;

namespace RayTracer.Tests.Geometry.Solvers;

public class PolynomialSolver_Roots
{
    // Ascending coefficients of k (x - r1)(x - r2)...
    private static double[] FromRoots(double k, params double[] r)
    {
        var c = new double[r.Length + 1];
        c[0] = k;
        int degree = 0;
        foreach (double root in r)
        {
            // Multiply by (x - root): shift up and subtract root times the old polynomial.
            for (int i = degree + 1; i >= 0; i--)
            {
                double shifted = i > 0 ? c[i - 1] : 0;
                c[i] = shifted - root * c[i];
            }

            degree++;
        }

        return c;
    }

    [Fact]
    public void Quartic_with_four_distinct_real_roots()
    {
        var random = new SeededRandom(41);
        Span<double> roots = stackalloc double[4];
        for (int n = 0; n < 2000; n++)
        {
            double[] expected = [.. Enumerable.Range(0, 4).Select(_ => random.NextDouble(-10, 10)).Order()];
            if (Enumerable.Range(1, 3).Any(i => expected[i] - expected[i - 1] < 0.05))
            {
                continue; // nearly double roots are covered separately
            }

            double[] c = FromRoots(random.NextDouble(0.5, 3), expected);
            int count = PolynomialSolver.SolveQuartic(c[0], c[1], c[2], c[3], c[4], roots);
            Assert.Equal(4, count);
            for (int i = 0; i < 4; i++)
            {
                Assert.True(Math.Abs(roots[i] - expected[i]) < 1e-6 * (1 + Math.Abs(expected[i])), $"root {i}: {roots[i]} vs {expected[i]}");
            }
        }
    }

    [Fact]
    public void Quartic_with_two_real_roots_and_a_complex_pair()
    {
        var random = new SeededRandom(42);
        Span<double> roots = stackalloc double[4];
        for (int n = 0; n < 1000; n++)
        {
            double r1 = random.NextDouble(-5, 5), r2 = r1 + random.NextDouble(0.1, 5);
            double re = random.NextDouble(-5, 5), im = random.NextDouble(0.2, 3);
            // (x - r1)(x - r2)(x² - 2 re x + re² + im²)
            double[] q = FromRoots(1, r1, r2);
            double[] p = [re * re + im * im, -2 * re, 1];
            var c = new double[5];
            for (int i = 0; i < 3; i++)
            {
                for (int j = 0; j < 3; j++)
                {
                    c[i + j] += q[i] * p[j];
                }
            }

            int count = PolynomialSolver.SolveQuartic(c[0], c[1], c[2], c[3], c[4], roots);
            Assert.Equal(2, count);
            Assert.Equal(r1, roots[0], 6);
            Assert.Equal(r2, roots[1], 6);
        }
    }

    [Fact]
    public void Quartic_with_no_real_roots()
    {
        Span<double> roots = stackalloc double[4];
        // (x² + 1)(x² + 4)
        Assert.Equal(0, PolynomialSolver.SolveQuartic(4, 0, 5, 0, 1, roots));
    }

    [Fact]
    public void Quartic_with_a_double_root_finds_it()
    {
        Span<double> roots = stackalloc double[4];
        double[] c = FromRoots(1, -2, 1, 1, 3);
        int count = PolynomialSolver.SolveQuartic(c[0], c[1], c[2], c[3], c[4], roots);
        Assert.InRange(count, 3, 4);
        Assert.Equal(-2, roots[0], 6);
        Assert.Equal(1, roots[1], 3);
        Assert.Equal(3, roots[count - 1], 6);
    }

    [Fact]
    public void Cubic_with_known_roots()
    {
        var random = new SeededRandom(43);
        Span<double> roots = stackalloc double[3];
        for (int n = 0; n < 1000; n++)
        {
            double[] expected = [.. Enumerable.Range(0, 3).Select(_ => random.NextDouble(-8, 8)).Order()];
            if (expected[1] - expected[0] < 0.05 || expected[2] - expected[1] < 0.05)
            {
                continue;
            }

            double[] c = FromRoots(random.NextDouble(-3, -0.5), expected);
            Assert.Equal(3, PolynomialSolver.SolveCubic(c[0], c[1], c[2], c[3], roots));
            for (int i = 0; i < 3; i++)
            {
                Assert.Equal(expected[i], roots[i], 7);
            }
        }
    }

    [Fact]
    public void Quadratic_is_accurate_when_roots_differ_greatly_in_size()
    {
        Span<double> roots = stackalloc double[2];
        // Roots 1e-8 and 1e8: the naive formula loses the small one entirely.
        Assert.Equal(2, PolynomialSolver.SolveQuadratic(1, -(1e8 + 1e-8), 1, roots));
        Assert.True(Math.Abs(roots[0] - 1e-8) < 1e-20, $"small root {roots[0]}");
        Assert.Equal(1e8, roots[1], 6);
        Assert.Equal(0, PolynomialSolver.SolveQuadratic(1, 0, 1, roots));
    }
}
