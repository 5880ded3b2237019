using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Instancing;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Tests.Geometry.Instancing;

public class Instancing_BadInput
{
    [Fact]
    public void A_zero_axis_is_refused_with_a_message_that_names_it()
    {
        var rstr = Assert.Throws<ArgumentException>(() => new RstrInstance(new GenericSphere(), Point3D.Origin, Vector3D.Zero));
        Assert.Contains("must not be the zero vector", rstr.Message);
        Assert.Equal("direction", rstr.ParamName);
        var tsr = Assert.Throws<ArgumentException>(() => TsrTransform.FromParts(Vector3D.Zero, Vector3D.Zero, 1, 1));
        Assert.Contains("rotation axis", tsr.Message);
        var cylinder = Assert.Throws<ArgumentException>(() => new GaUniversalCylinder(Point3D.Origin, Vector3D.Zero, 1));
        Assert.Contains("non-zero", cylinder.Message);
    }

    [Fact]
    public void A_non_uniform_scale_is_refused_for_a_tsr_instance()
    {
        var frame = new FrameOfReference(new TwistableVector(2, 0, 0), new TwistableVector(0, 1, 0), default);
        var error = Assert.Throws<ArgumentException>(() => new TsrInstance(new GenericSphere(), frame));
        Assert.Contains("uniform scale", error.Message);
        Assert.Contains("x by 2 and y by 1", error.Message);
    }

    [Fact]
    public void A_singular_or_sheared_frame_of_reference_is_refused()
    {
        var parallel = new FrameOfReference(new TwistableVector(1, 1, 0), new TwistableVector(-2, -2, 0), default);
        Assert.Contains("parallel", Assert.Throws<ArgumentException>(() => TsrTransform.FromFrame(parallel)).Message);
        var zero = new FrameOfReference(new TwistableVector(0, 0, 0), new TwistableVector(0, 1, 0), default);
        Assert.Contains("singular", Assert.Throws<ArgumentException>(() => TsrTransform.FromFrame(zero)).Message);
        var sheared = new FrameOfReference(new TwistableVector(1, 0, 0), new TwistableVector(0.6, 0.8, 0), default);
        Assert.Contains("not perpendicular", Assert.Throws<ArgumentException>(() => TsrTransform.FromFrame(sheared)).Message);
        var infinite = new FrameOfReference(new TwistableVector(double.NaN, 0, 0), new TwistableVector(0, 1, 0), default);
        Assert.Contains("non-finite", Assert.Throws<ArgumentException>(() => TsrTransform.FromFrame(infinite)).Message);
    }

    [Fact]
    public void A_scale_of_zero_is_refused_by_twister_before_it_reaches_the_frame()
    {
        Assert.Throws<ArgumentException>(() => FrameOfReference.Identity.Scaled(0));
        Assert.Throws<ArgumentOutOfRangeException>(() => TsrTransform.FromParts(Vector3D.Zero, Vector3D.UnitY, 0, 0));
    }
}
