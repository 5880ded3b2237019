using Twister;

namespace Twister.Tests;

/// <summary>Bad input fails at once, naming the parameter, instead of producing NaN.</summary>
public sealed class BadInputTests
{
    [Fact]
    public void Zero_length_axis_is_refused()
    {
        var e = Assert.Throws<ArgumentException>(() => new RotationTwist(new(0, 0, 0), default, 1, ParameterMap.U));
        Assert.Equal("axis", e.ParamName);
        Assert.Contains("zero length", e.Message);
        Assert.Equal("axis", Assert.Throws<ArgumentException>(() => new FullTwist(default, default, 1, 1)).ParamName);
        Assert.Equal("normal", Assert.Throws<ArgumentException>(() => new ReflectionTwist(default, default)).ParamName);
    }

    [Theory]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    [InlineData(double.NegativeInfinity)]
    public void Non_finite_numbers_are_refused(double bad)
    {
        Assert.Equal("coefficient", Assert.Throws<ArgumentException>(() => new RotationTwist(new(0, 0, 1), default, bad, ParameterMap.U)).ParamName);
        Assert.Equal("coefficient", Assert.Throws<ArgumentException>(() => new TranslationTwist(new(1, 0, 0), bad, ParameterMap.U)).ParamName);
        Assert.Equal("slideCoefficient", Assert.Throws<ArgumentException>(() => new FullTwist(new(0, 0, 1), default, 1, ParameterMap.U, bad, ParameterMap.U)).ParamName);
        Assert.Equal("axis", Assert.Throws<ArgumentException>(() => new RotationTwist(new(bad, 0, 1), default, 1, ParameterMap.U)).ParamName);
        Assert.Equal("origin", Assert.Throws<ArgumentException>(() => new RotationTwist(new(0, 0, 1), new(0, bad, 0), 1, ParameterMap.U)).ParamName);
        Assert.Equal("b", Assert.Throws<ArgumentException>(() => ParameterMap.Affine(1, bad, 0)).ParamName);
        Assert.Equal("radius", Assert.Throws<ArgumentException>(() => TwistSurfaces.Sphere(default, bad)).ParamName);
        Assert.Equal("factor", Assert.Throws<ArgumentException>(() => ScalingTwist.ByFactor(default, bad)).ParamName);

        var circle = TwistCurves.Circle(default, 1);
        Assert.Equal("t", Assert.Throws<ArgumentException>(() => circle.PointAt(bad)).ParamName);
        Assert.Equal("t", Assert.Throws<ArgumentException>(() => circle.TangentAt(bad)).ParamName);
        var torus = TwistSurfaces.Torus(2, 1);
        Assert.Equal("u", Assert.Throws<ArgumentException>(() => torus.PointAt(bad, 0)).ParamName);
        Assert.Equal("v", Assert.Throws<ArgumentException>(() => torus.NormalAt(0, bad)).ParamName);
        Assert.Equal("v", Assert.Throws<ArgumentException>(() => TwistSurfaces.Cone(1, 1).NormalAt(0.5, bad)).ParamName);
    }

    [Fact]
    public void A_user_map_that_returns_nan_is_reported_with_the_parameters()
    {
        var map = ParameterMap.OfU(u => Math.Sqrt(u - 0.5), u => 0.5 / Math.Sqrt(u - 0.5));
        var curve = new TwistCurve(new(1, 0, 0), TwistCascade.Empty.RotateAboutZ(1, map));
        var e = Assert.Throws<ArgumentException>(() => curve.PointAt(0.25));
        Assert.Contains("(0.25, 0)", e.Message);
    }

    [Fact]
    public void A_curve_refuses_twists_that_depend_on_v()
    {
        var e = Assert.Throws<ArgumentException>(() => new TwistCurve(default, TwistCascade.Empty.RotateAboutZ(1, ParameterMap.V)));
        Assert.Equal("cascade", e.ParamName);
    }

    [Fact]
    public void A_scaling_beyond_the_range_of_doubles_is_refused()
    {
        var twist = new ScalingTwist(default, 1e3, ParameterMap.U);
        var e = Assert.Throws<ArgumentException>(() => twist.Apply(new TwistablePoint(1, 1, 1), 1, 0));
        Assert.Contains("out of range", e.Message);
    }
}
