using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>Embree 3's <c>RTCRay8</c>: <see cref="EmbreeRay"/>'s fields, each for 8 rays; 384 bytes, 32-byte aligned natively.</summary>
[StructLayout(LayoutKind.Sequential, Size = 384)]
internal unsafe struct EmbreeRay8
{
    public fixed float OrgX[8];
    public fixed float OrgY[8];
    public fixed float OrgZ[8];
    public fixed float TNear[8];
    public fixed float DirX[8];
    public fixed float DirY[8];
    public fixed float DirZ[8];
    public fixed float Time[8];
    public fixed float TFar[8];
    public fixed uint Mask[8];
    public fixed uint Id[8];
    public fixed uint Flags[8];
}
