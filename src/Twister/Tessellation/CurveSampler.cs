namespace Twister.Tessellation;

/// <summary>
/// Adaptive sampling of a parametric curve with multiple random probing (de Figueiredo, Graphics
/// Gems V, 1995). Each segment [t0, t1] is probed at random parameters, one in each of
/// <see cref="TessellationOptions.ProbeCount"/> equal strata; where a probe's curve point lies farther
/// than the tolerance from the chord point at the same fraction of the segment, the segment is
/// halved and both halves are probed again. Random probes do not fall into step with a periodic
/// curve, as evenly spaced ones can.
/// </summary>
public static class CurveSampler
{
    public static Polyline Sample(IParametricCurve curve, TessellationOptions options)
    {
        ArgumentNullException.ThrowIfNull(curve);
        ArgumentNullException.ThrowIfNull(options);
        options.Validate();
        var run = new Run(curve, options);
        var start = run.Evaluate(0);
        run.Parameters.Add(0);
        run.Points.Add(start);
        var p0 = start;
        for (var i = 0; i < options.InitialCells; i++)
        {
            var t0 = (double)i / options.InitialCells;
            var t1 = (double)(i + 1) / options.InitialCells;
            var p1 = run.Evaluate(t1);
            run.Refine(t0, p0, t1, p1, 0);
            run.Append(t1, p1);
            p0 = p1;
        }

        return new Polyline([.. run.Parameters], [.. run.Points]);
    }

    private sealed class Run(IParametricCurve curve, TessellationOptions options)
    {
        private readonly ProbeRandom _random = new(options.Seed);
        private readonly double _limit = Acceptance.Fraction * options.Tolerance;

        public List<double> Parameters { get; } = [];

        public List<TwistablePoint> Points { get; } = [];

        public TwistablePoint Evaluate(double t)
        {
            var p = curve.PointAt(t);
            if (!Geometry3.IsFinite(p))
            {
                throw new TessellationException(FormattableString.Invariant($"The curve has a non-finite point {p} at t = {t}."));
            }

            return p;
        }

        public void Append(double t, TwistablePoint p)
        {
            if (Points.Count > options.MaxSegments)
            {
                throw new TessellationException(FormattableString.Invariant(
                    $"Sampling the curve to tolerance {options.Tolerance} needs more than the budget of {options.MaxSegments} segments; raise the tolerance or the budget."));
            }

            Parameters.Add(t);
            Points.Add(p);
        }

        /// <summary>Appends the interior samples of (t0, t1), in order; the caller appends t1.</summary>
        public void Refine(double t0, TwistablePoint p0, double t1, TwistablePoint p1, int depth)
        {
            if (IsFlat(t0, p0, t1, p1))
            {
                return;
            }

            if (depth >= Acceptance.MaxDepth)
            {
                throw new TessellationException(FormattableString.Invariant(
                    $"The curve does not flatten to tolerance {options.Tolerance} near t = {t0}: it may have a kink or a jump there, or the tolerance is below its rounding noise."));
            }

            var tm = 0.5 * (t0 + t1);
            var pm = Evaluate(tm);
            Refine(t0, p0, tm, pm, depth + 1);
            Append(tm, pm);
            Refine(tm, pm, t1, p1, depth + 1);
        }

        private bool IsFlat(double t0, TwistablePoint p0, double t1, TwistablePoint p1)
        {
            var n = options.ProbeCount;
            for (var i = 0; i < n; i++)
            {
                var s = (i + _random.NextDouble()) / n;
                var q = Evaluate(t0 + s * (t1 - t0));
                if (Geometry3.Distance(q, Geometry3.Lerp(p0, p1, s)) > _limit)
                {
                    return false;
                }
            }

            return true;
        }
    }
}
