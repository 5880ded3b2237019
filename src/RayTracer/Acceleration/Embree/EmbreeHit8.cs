using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>Embree 3's <c>RTCHit8</c> with one instance level: <see cref="EmbreeHit"/>'s fields for 8 rays; 256 bytes.</summary>
[StructLayout(LayoutKind.Sequential, Size = 256)]
internal unsafe struct EmbreeHit8
{
    public fixed float NgX[8];
    public fixed float NgY[8];
    public fixed float NgZ[8];
    public fixed float U[8];
    public fixed float V[8];
    public fixed uint PrimId[8];
    public fixed uint GeomId[8];
    public fixed uint InstId0[8];
}
