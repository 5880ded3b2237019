using Twister.Tessellation;
using Twister.Tests.Tessellation.Shapes;

namespace Twister.Tests.Tessellation;

public class CurveSampler_Accuracy
{
    private static double MaxChordError(IParametricCurve curve, Polyline line, int samples = 64)
    {
        var random = new Random(11);
        var worst = 0.0;
        for (var k = 0; k < line.SegmentCount; k++)
        {
            double t0 = line.Parameters[k], t1 = line.Parameters[k + 1];
            TwistablePoint p0 = line.Points[k], p1 = line.Points[k + 1];
            for (var i = 0; i < samples; i++)
            {
                var s = random.NextDouble();
                var chord = new TwistablePoint(p0.x + s * (p1.x - p0.x), p0.y + s * (p1.y - p0.y), p0.z + s * (p1.z - p0.z));
                worst = Math.Max(worst, MeshMeasure.Distance(curve.PointAt(t0 + s * (t1 - t0)), chord));
            }
        }

        return worst;
    }

    [Theory]
    [InlineData("circle", 1e-2)]
    [InlineData("circle", 1e-4)]
    [InlineData("helix", 1e-3)]
    [InlineData("rose", 1e-3)]
    public void Chord_error_at_random_parameters_is_within_the_tolerance(string name, double tolerance)
    {
        var curve = ClosedFormCurve.ByName(name);
        var line = CurveSampler.Sample(curve, new TessellationOptions(tolerance));
        Assert.True(line.SegmentCount > 4);
        Assert.Equal(0, line.Parameters[0]);
        Assert.Equal(1, line.Parameters[^1]);
        Assert.True(line.Parameters.Zip(line.Parameters.Skip(1)).All(p => p.First < p.Second));
        for (var k = 0; k < line.Points.Count; k++)
        {
            Assert.Equal(0, MeshMeasure.Distance(curve.PointAt(line.Parameters[k]), line.Points[k]));
        }

        Assert.InRange(MaxChordError(curve, line), 0, tolerance);
    }

    [Fact]
    public void The_same_seed_gives_the_same_samples()
    {
        var options = new TessellationOptions(1e-3) { Seed = 5 };
        var first = CurveSampler.Sample(ClosedFormCurve.Rose(), options);
        var second = CurveSampler.Sample(ClosedFormCurve.Rose(), options);
        Assert.Equal(first.Parameters, second.Parameters);
    }

    [Fact]
    public void Samples_crowd_where_the_curve_bends()
    {
        // A flat ellipse bends a thousand times harder at the ends of its long axis (t = 0) than at
        // the ends of its short axis (t = 1/4), while its speed there differs only tenfold.
        var ellipse = new ClosedFormCurve(
            "ellipse",
            t => new(Math.Cos(2 * Math.PI * t), 0.1 * Math.Sin(2 * Math.PI * t), 0),
            t => new(-2 * Math.PI * Math.Sin(2 * Math.PI * t), 0.2 * Math.PI * Math.Cos(2 * Math.PI * t), 0));
        var line = CurveSampler.Sample(ellipse, new TessellationOptions(1e-4));
        double SpacingAt(double t) => line.Parameters.Zip(line.Parameters.Skip(1))
            .Where(p => p.First <= t && t < p.Second).Select(p => p.Second - p.First).Single();
        Assert.True(SpacingAt(0.001) < SpacingAt(0.25) / 2);
    }
}
