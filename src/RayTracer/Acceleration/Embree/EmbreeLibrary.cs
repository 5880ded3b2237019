using System.Runtime.InteropServices;

namespace RayTracer.Acceleration.Embree;

/// <summary>
/// The few Embree 3 entry points the benchmark needs, bound at run time from <c>libembree3.so.3</c> (Debian
/// package <c>libembree3-3</c>) so that nothing in the project needs Embree to build or to run.
/// </summary>
internal static unsafe class EmbreeLibrary
{
    public const string FileName = "libembree3.so.3";
    public const uint InvalidGeometryId = uint.MaxValue;
    public const int GeometryTypeTriangle = 0;
    public const int BufferTypeIndex = 0, BufferTypeVertex = 1;
    public const int FormatUInt3 = 0x5003, FormatFloat3 = 0x9003;

    private static readonly Lock Gate = new();
    private static bool _tried;
    private static string? _problem;

    public static delegate* unmanaged<byte*, nint> NewDevice;
    public static delegate* unmanaged<nint, void> ReleaseDevice;
    public static delegate* unmanaged<nint, int> GetDeviceError;
    public static delegate* unmanaged<nint, nint> NewScene;
    public static delegate* unmanaged<nint, void> CommitScene;
    public static delegate* unmanaged<nint, void> ReleaseScene;
    public static delegate* unmanaged<nint, int, nint> NewGeometry;
    public static delegate* unmanaged<nint, int, uint, int, nuint, nuint, void*> SetNewGeometryBuffer;
    public static delegate* unmanaged<nint, void> CommitGeometry;
    public static delegate* unmanaged<nint, nint, uint> AttachGeometry;
    public static delegate* unmanaged<nint, void> ReleaseGeometry;

    // A single-ray query takes a few hundred nanoseconds and never calls back into .NET, so the GC
    // transition (tens of nanoseconds) is skipped: with it the comparison would time the interop.
    public static delegate* unmanaged[SuppressGCTransition]<nint, EmbreeIntersectContext*, EmbreeRayHit*, void> Intersect1;
    public static delegate* unmanaged[SuppressGCTransition]<nint, EmbreeIntersectContext*, EmbreeRay*, void> Occluded1;
    public static delegate* unmanaged[SuppressGCTransition]<int*, nint, EmbreeIntersectContext*, EmbreeRayHit8*, void> Intersect8;
    public static delegate* unmanaged[SuppressGCTransition]<int*, nint, EmbreeIntersectContext*, EmbreeRay8*, void> Occluded8;

    /// <summary>Loads the library once; false with the reason when it is missing or lacks an entry point.</summary>
    public static bool TryLoad(out string? problem)
    {
        lock (Gate)
        {
            if (!_tried)
            {
                _tried = true;
                _problem = Load();
            }

            problem = _problem;
            return problem is null;
        }
    }

    private static string? Load()
    {
        if (!NativeLibrary.TryLoad(FileName, out var handle))
            return $"{FileName} not found (on Debian or Ubuntu: apt-get install libembree3-3)";
        try
        {
            NewDevice = (delegate* unmanaged<byte*, nint>)NativeLibrary.GetExport(handle, "rtcNewDevice");
            ReleaseDevice = (delegate* unmanaged<nint, void>)NativeLibrary.GetExport(handle, "rtcReleaseDevice");
            GetDeviceError = (delegate* unmanaged<nint, int>)NativeLibrary.GetExport(handle, "rtcGetDeviceError");
            NewScene = (delegate* unmanaged<nint, nint>)NativeLibrary.GetExport(handle, "rtcNewScene");
            CommitScene = (delegate* unmanaged<nint, void>)NativeLibrary.GetExport(handle, "rtcCommitScene");
            ReleaseScene = (delegate* unmanaged<nint, void>)NativeLibrary.GetExport(handle, "rtcReleaseScene");
            NewGeometry = (delegate* unmanaged<nint, int, nint>)NativeLibrary.GetExport(handle, "rtcNewGeometry");
            SetNewGeometryBuffer = (delegate* unmanaged<nint, int, uint, int, nuint, nuint, void*>)NativeLibrary.GetExport(handle, "rtcSetNewGeometryBuffer");
            CommitGeometry = (delegate* unmanaged<nint, void>)NativeLibrary.GetExport(handle, "rtcCommitGeometry");
            AttachGeometry = (delegate* unmanaged<nint, nint, uint>)NativeLibrary.GetExport(handle, "rtcAttachGeometry");
            ReleaseGeometry = (delegate* unmanaged<nint, void>)NativeLibrary.GetExport(handle, "rtcReleaseGeometry");
            Intersect1 = (delegate* unmanaged[SuppressGCTransition]<nint, EmbreeIntersectContext*, EmbreeRayHit*, void>)NativeLibrary.GetExport(handle, "rtcIntersect1");
            Occluded1 = (delegate* unmanaged[SuppressGCTransition]<nint, EmbreeIntersectContext*, EmbreeRay*, void>)NativeLibrary.GetExport(handle, "rtcOccluded1");
            Intersect8 = (delegate* unmanaged[SuppressGCTransition]<int*, nint, EmbreeIntersectContext*, EmbreeRayHit8*, void>)NativeLibrary.GetExport(handle, "rtcIntersect8");
            Occluded8 = (delegate* unmanaged[SuppressGCTransition]<int*, nint, EmbreeIntersectContext*, EmbreeRay8*, void>)NativeLibrary.GetExport(handle, "rtcOccluded8");
        }
        catch (EntryPointNotFoundException e)
        {
            return $"{FileName} is not Embree 3: {e.Message}";
        }

        return null;
    }
}
