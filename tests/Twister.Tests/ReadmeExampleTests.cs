using Twister;

namespace Twister.Tests;

/// <summary>The usage example of docs/twister.md, kept compiling and true.</summary>
public sealed class ReadmeExampleTests
{
    [Fact]
    public void Readme_example_builds_a_helix_and_a_torus()
    {
        // A helix: the seed (0, 0, 0) moved 1 along x, turned about z by 2π·3u, lifted by u.
        var helix = new TwistCurve(new TwistablePoint(0, 0, 0), TwistCascade.Empty
            .Translate(new TwistableVector(1, 0, 0), 1, ParameterMap.One)
            .RotateAboutZ(2 * Math.PI * 3, ParameterMap.U)
            .Translate(new TwistableVector(0, 0, 1), 1, ParameterMap.U));
        var p = helix.PointAt(0.25);          // (0, -1, 0.25): three quarter turns
        var tangent = helix.TangentAt(0.25);  // ∂U/∂t from the generated kernels
        var torus = TwistSurfaces.Torus(majorRadius: 2, minorRadius: 0.5);
        var normal = torus.NormalAt(0.1, 0.3); // outward, not normalised

        Near.Equal(new TwistablePoint(0, -1, 0.25), p, 1e-12, "point");
        Near.Equal(new TwistableVector(6 * Math.PI, 0, 1), tangent, 1e-12, "tangent");
        var q = torus.PointAt(0.1, 0.3);
        Assert.True(Near.Dot(normal, new(q.x - 2 * Math.Cos(0.6 * Math.PI), q.y - 2 * Math.Sin(0.6 * Math.PI), q.z)) > 0);
    }
}
