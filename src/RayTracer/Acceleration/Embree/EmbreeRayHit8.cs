using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>Embree 3's <c>RTCRayHit8</c>: the rays, then the hits at byte 384; 640 bytes, 32-byte aligned natively.</summary>
[StructLayout(LayoutKind.Sequential, Size = 640)]
internal struct EmbreeRayHit8
{
    public EmbreeRay8 Ray;
    public EmbreeHit8 Hit;
}
