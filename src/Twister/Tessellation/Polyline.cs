namespace Twister.Tessellation;

/// <summary>A sampled curve: increasing parameters from 0 to 1 and the curve's points at them.</summary>
public sealed class Polyline
{
    internal Polyline(double[] parameters, TwistablePoint[] points)
    {
        Parameters = parameters;
        Points = points;
    }

    public IReadOnlyList<double> Parameters { get; }

    public IReadOnlyList<TwistablePoint> Points { get; }

    public int SegmentCount => Points.Count - 1;
}
