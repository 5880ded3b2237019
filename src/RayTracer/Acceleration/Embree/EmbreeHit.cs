using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>
/// Embree 3's <c>RTCHit</c> (rtcore_ray.h) as built with <c>RTC_MAX_INSTANCE_LEVEL_COUNT</c> 1, the
/// default and the Debian package's setting: 32 bytes, 16-byte aligned natively.
/// </summary>
[StructLayout(LayoutKind.Sequential, Size = 32)]
internal struct EmbreeHit
{
    public float NgX, NgY, NgZ;
    public float U, V;
    public uint PrimId;
    public uint GeomId;
    public uint InstId0;
}
