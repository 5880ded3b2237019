using System.Runtime.Intrinsics;

namespace RayTracer.Tests.Acceleration;

/// <summary>
/// The node widths the BVH can be built with on this machine: four-wide always (the fallback), eight-wide
/// where <see cref="Vector512"/> is accelerated. Tests run each traversal they can.
/// </summary>
internal static class BvhWidths
{
    public static int[] Available => Vector512.IsHardwareAccelerated ? [4, 8] : [4];
}
