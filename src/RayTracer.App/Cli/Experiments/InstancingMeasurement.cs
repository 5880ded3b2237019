using RayTracer.Scenes.Instancing;

namespace RayTracer.Cli.Experiments;

/// <summary>
/// One scene rendered by one cylinder method: what Table 7-2 lists (the test time is that of the
/// tube tests alone, replayed), the wall time of a whole render, and how far its image is from U-Cyl's.
/// </summary>
internal sealed record InstancingMeasurement(
    string Scene,
    CylinderMethod Method,
    int Objects,
    long Rays,
    long TestInvocations,
    double TimeMilliseconds,
    double RenderMilliseconds,
    double BytesPerObject,
    double MaxPixelDifference,
    int PixelsOverTolerance)
{
    public double TotalKilobytes => BytesPerObject * Objects / 1024;
}
