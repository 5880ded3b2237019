using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>
/// Embree 3's <c>RTCIntersectContext</c> with one instance level and no minimum curve width (the
/// package's build): flags, filter pointer, one instance id; 24 bytes. <see cref="Incoherent"/> does what
/// the header's inline <c>rtcInitIntersectContext</c> does, which no library exports.
/// </summary>
[StructLayout(LayoutKind.Sequential)]
internal struct EmbreeIntersectContext
{
    public int Flags;
    public nint Filter;
    public uint InstId0;

    /// <summary>RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT, no filter, no instance on the stack.</summary>
    public static EmbreeIntersectContext Incoherent => new() { Flags = 0, Filter = 0, InstId0 = EmbreeLibrary.InvalidGeometryId };

    /// <summary>As <see cref="Incoherent"/> with RTC_INTERSECT_CONTEXT_FLAG_COHERENT: the hint for packets of neighbouring rays.</summary>
    public static EmbreeIntersectContext Coherent => new() { Flags = 1, Filter = 0, InstId0 = EmbreeLibrary.InvalidGeometryId };
}
