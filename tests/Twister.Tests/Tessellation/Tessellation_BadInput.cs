using Twister.Tessellation;
using Twister.Tests.Tessellation.Shapes;

namespace Twister.Tests.Tessellation;

public class Tessellation_BadInput
{
    [Theory]
    [InlineData(0.0)]
    [InlineData(-1e-3)]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    public void A_tolerance_that_is_not_a_positive_finite_distance_is_refused(double tolerance)
    {
        var surfaceError = Assert.Throws<ArgumentOutOfRangeException>(() => SurfaceTessellator.Tessellate(new SphereSurface(1), new TessellationOptions(tolerance)));
        var curveError = Assert.Throws<ArgumentOutOfRangeException>(() => CurveSampler.Sample(ClosedFormCurve.Circle(1), new TessellationOptions(tolerance)));
        Assert.Contains("tolerance must be a positive finite distance", surfaceError.Message);
        Assert.Contains("tolerance must be a positive finite distance", curveError.Message);
    }

    [Fact]
    public void A_non_finite_surface_point_is_reported_with_its_parameters()
    {
        var error = Assert.Throws<TessellationException>(() => SurfaceTessellator.Tessellate(new FaultySurface(), new TessellationOptions(1e-3)));
        Assert.Contains("non-finite point", error.Message);
        Assert.Contains("(u, v) = (", error.Message);
    }

    [Fact]
    public void A_non_finite_curve_point_is_reported_with_its_parameter()
    {
        var curve = new ClosedFormCurve("broken", t => new(t, t > 0.7 ? double.PositiveInfinity : 0, 0), t => new(1, 0, 0));
        var error = Assert.Throws<TessellationException>(() => CurveSampler.Sample(curve, new TessellationOptions(1e-3)));
        Assert.Contains("non-finite point", error.Message);
        Assert.Contains("at t = ", error.Message);
    }

    [Fact]
    public void A_tolerance_too_fine_for_the_triangle_budget_stops_early_with_a_clear_message()
    {
        // A torus to a nanometre would need hundreds of millions of triangles; the run must stop at the budget.
        var options = new TessellationOptions(1e-9) { MaxTriangles = 20_000 };
        var error = Assert.Throws<TessellationException>(() => SurfaceTessellator.Tessellate(new TorusSurface(1, 0.35), options));
        Assert.Contains("more than the budget of 20000 triangles", error.Message);
    }

    [Fact]
    public void A_tolerance_too_fine_for_the_segment_budget_stops_early_with_a_clear_message()
    {
        var options = new TessellationOptions(1e-9) { MaxSegments = 1000 };
        var error = Assert.Throws<TessellationException>(() => CurveSampler.Sample(ClosedFormCurve.Helix(0.5, 2), options));
        Assert.Contains("more than the budget of 1000 segments", error.Message);
    }

    [Fact]
    public void The_default_budget_is_two_million()
    {
        var options = new TessellationOptions(1e-3);
        Assert.Equal(2_000_000, options.MaxTriangles);
        Assert.Equal(2_000_000, options.MaxSegments);
    }

    [Fact]
    public void A_surface_that_is_only_a_point_is_refused()
    {
        var point = new ConstantSurface();
        var error = Assert.Throws<TessellationException>(() => SurfaceTessellator.Tessellate(point, new TessellationOptions(1e-3)));
        Assert.Contains("degenerate", error.Message);
    }

    private sealed class ConstantSurface : IParametricSurface
    {
        public TwistablePoint PointAt(double u, double v) => new(1, 2, 3);

        public TwistableVector NormalAt(double u, double v) => new(0, 0, 0);
    }
}
