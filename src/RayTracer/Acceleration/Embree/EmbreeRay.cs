using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>
/// Embree 3's <c>RTCRay</c> (rtcore_ray.h): 48 bytes. The native struct is 16-byte aligned, which C#
/// cannot declare, so callers place it at an aligned address themselves.
/// </summary>
[StructLayout(LayoutKind.Sequential, Size = 48)]
internal struct EmbreeRay
{
    public float OrgX, OrgY, OrgZ;
    public float TNear;
    public float DirX, DirY, DirZ;
    public float Time;

    /// <summary>End of the segment; set to the hit distance, or to −∞ by an occlusion query that finds a hit.</summary>
    public float TFar;
    public uint Mask;
    public uint Id;
    public uint Flags;
}
