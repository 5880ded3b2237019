namespace RayTracer.Geometry.Solvers;

/// <summary>
/// Real roots of polynomials up to degree four, given by coefficients c[0] + c[1] x + ... .
/// Closed forms (after Schwarze, Graphics Gems I) followed by Newton polishing on the original
/// polynomial: the closed forms lose digits when roots are close or coefficients vary widely,
/// and a few Newton steps restore them cheaply.
/// </summary>
public static class PolynomialSolver
{
    private const double ZeroTolerance = 1e-12;

    /// <summary>Real roots of c2 x² + c1 x + c0, ascending. Degenerates to the linear case when c2 = 0.</summary>
    public static int SolveQuadratic(double c0, double c1, double c2, Span<double> roots)
    {
        if (c2 == 0)
        {
            if (c1 == 0)
            {
                return 0;
            }

            roots[0] = -c0 / c1;
            return 1;
        }

        double disc = c1 * c1 - 4 * c2 * c0;
        if (disc < 0)
        {
            return 0;
        }

        if (disc == 0)
        {
            roots[0] = -0.5 * c1 / c2;
            return 1;
        }

        // Avoids cancellation between -c1 and sqrt(disc).
        double q = -0.5 * (c1 + Math.CopySign(Math.Sqrt(disc), c1));
        double r0 = q / c2;
        double r1 = q != 0 ? c0 / q : -r0;
        if (r0 > r1)
        {
            (r0, r1) = (r1, r0);
        }

        roots[0] = r0;
        roots[1] = r1;
        return 2;
    }

    /// <summary>Real roots of c3 x³ + c2 x² + c1 x + c0 (c3 ≠ 0), ascending; multiple roots reported once.</summary>
    public static int SolveCubic(double c0, double c1, double c2, double c3, Span<double> roots)
    {
        if (c3 == 0)
        {
            return SolveQuadratic(c0, c1, c2, roots);
        }

        int n = SolveNormalizedCubic(c2 / c3, c1 / c3, c0 / c3, roots);
        for (int i = 0; i < n; i++)
        {
            roots[i] = Polish(roots[i], c0, c1, c2, c3, 0);
        }

        SortAscending(roots[..n]);
        return n;
    }

    /// <summary>Real roots of c4 x⁴ + c3 x³ + c2 x² + c1 x + c0, ascending.</summary>
    public static int SolveQuartic(double c0, double c1, double c2, double c3, double c4, Span<double> roots)
    {
        if (c4 == 0)
        {
            return SolveCubic(c0, c1, c2, c3, roots);
        }

        double a = c3 / c4, b = c2 / c4, c = c1 / c4, d = c0 / c4;

        // Depressed quartic y⁴ + p y² + q y + r with x = y - a/4.
        double sqA = a * a;
        double p = -3.0 / 8 * sqA + b;
        double q = 1.0 / 8 * sqA * a - 0.5 * a * b + c;
        double r = -3.0 / 256 * sqA * sqA + 1.0 / 16 * sqA * b - 0.25 * a * c + d;

        Span<double> s = stackalloc double[4];
        int n;
        if (IsZero(r))
        {
            // y (y³ + p y + q) = 0
            n = SolveNormalizedCubic(0, p, q, s);
            s[n++] = 0;
        }
        else
        {
            // Resolvent cubic z³ - p/2 z² - r z + (r p / 2 - q² / 8); any real root works,
            // the largest gives the best conditioned square roots below.
            Span<double> z3 = stackalloc double[3];
            int m = SolveNormalizedCubic(-0.5 * p, -r, 0.5 * r * p - 0.125 * q * q, z3);
            double z = z3[0];
            for (int i = 1; i < m; i++)
            {
                z = Math.Max(z, z3[i]);
            }

            double u = z * z - r;
            double v = 2 * z - p;
            if (IsZero(u))
            {
                u = 0;
            }
            else if (u > 0)
            {
                u = Math.Sqrt(u);
            }
            else
            {
                return 0;
            }

            if (IsZero(v))
            {
                v = 0;
            }
            else if (v > 0)
            {
                v = Math.Sqrt(v);
            }
            else
            {
                return 0;
            }

            n = SolveQuadratic(z - u, q < 0 ? -v : v, 1, s);
            n += SolveQuadratic(z + u, q < 0 ? v : -v, 1, s[n..]);
        }

        double shift = 0.25 * a;
        for (int i = 0; i < n; i++)
        {
            roots[i] = Polish(s[i] - shift, c0, c1, c2, c3, c4);
        }

        SortAscending(roots[..n]);
        return n;
    }

    /// <summary>Evaluates c0 + c1 x + ... + c4 x⁴ (Horner).</summary>
    public static double Evaluate(double x, double c0, double c1, double c2, double c3, double c4) =>
        (((c4 * x + c3) * x + c2) * x + c1) * x + c0;

    // Roots of x³ + a x² + b x + c.
    private static int SolveNormalizedCubic(double a, double b, double c, Span<double> roots)
    {
        double sqA = a * a;
        double p = 1.0 / 3 * (-1.0 / 3 * sqA + b);
        double q = 0.5 * (2.0 / 27 * a * sqA - 1.0 / 3 * a * b + c);
        double cbP = p * p * p;
        double disc = q * q + cbP;
        int n;

        if (IsZero(disc))
        {
            if (IsZero(q))
            {
                roots[0] = 0;
                n = 1;
            }
            else
            {
                double u = Math.Cbrt(-q);
                roots[0] = 2 * u;
                roots[1] = -u;
                n = 2;
            }
        }
        else if (disc < 0)
        {
            // Three real roots: trigonometric form.
            double phi = 1.0 / 3 * Math.Acos(Math.Clamp(-q / Math.Sqrt(-cbP), -1, 1));
            double t = 2 * Math.Sqrt(-p);
            roots[0] = t * Math.Cos(phi);
            roots[1] = -t * Math.Cos(phi + Math.PI / 3);
            roots[2] = -t * Math.Cos(phi - Math.PI / 3);
            n = 3;
        }
        else
        {
            double sqrtD = Math.Sqrt(disc);
            roots[0] = Math.Cbrt(sqrtD - q) - Math.Cbrt(sqrtD + q);
            n = 1;
        }

        double shift = 1.0 / 3 * a;
        for (int i = 0; i < n; i++)
        {
            roots[i] -= shift;
        }

        return n;
    }

    private static double Polish(double x, double c0, double c1, double c2, double c3, double c4)
    {
        for (int i = 0; i < 4; i++)
        {
            double f = Evaluate(x, c0, c1, c2, c3, c4);
            double df = ((4 * c4 * x + 3 * c3) * x + 2 * c2) * x + c1;
            if (df == 0 || !double.IsFinite(f))
            {
                break;
            }

            double next = x - f / df;
            // Only accept steps that do not make the residual worse (Newton can jump near double roots).
            if (Math.Abs(Evaluate(next, c0, c1, c2, c3, c4)) > Math.Abs(f))
            {
                break;
            }

            x = next;
        }

        return x;
    }

    private static bool IsZero(double x) => Math.Abs(x) < ZeroTolerance;

    private static void SortAscending(Span<double> values)
    {
        for (int i = 1; i < values.Length; i++)
        {
            double v = values[i];
            int j = i - 1;
            while (j >= 0 && values[j] > v)
            {
                values[j + 1] = values[j];
                j--;
            }

            values[j + 1] = v;
        }
    }
}
