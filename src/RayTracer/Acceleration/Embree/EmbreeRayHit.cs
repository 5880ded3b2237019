using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>Embree 3's <c>RTCRayHit</c>: the ray, then the hit at byte 48; 80 bytes, 16-byte aligned natively.</summary>
[StructLayout(LayoutKind.Sequential, Size = 80)]
internal struct EmbreeRayHit
{
    public EmbreeRay Ray;
    public EmbreeHit Hit;
}
