using System.Runtime.CompilerServices;
using System.Text;
using RayTracer.Geometry.Meshes;
using RayTracer.Tracing;

namespace RayTracer.Acceleration.Embree;

/// <summary>
/// An Embree scene holding one triangle mesh, its vertices rounded to float as Embree stores them, on a
/// device of its own or on another scene's; queried one ray at a time like our structures, for
/// side-by-side measurements.
/// </summary>
internal sealed unsafe class EmbreeScene : IRayQueries, IDisposable
{
    private nint _device;
    private nint _scene;

    // A scene made on another scene's device leaves the device to that scene.
    private readonly bool _ownsDevice;

    private EmbreeScene(nint device, nint scene, bool ownsDevice)
    {
        _device = device;
        _scene = scene;
        _ownsDevice = ownsDevice;
    }

    /// <summary>
    /// Builds the scene with Embree's default (medium) quality on <paramref name="threads"/> threads. Null
    /// with the reason when Embree is not installed or refuses the mesh.
    /// </summary>
    public static EmbreeScene? TryCreate(Mesh mesh, int threads, out string? problem)
    {
        ArgumentNullException.ThrowIfNull(mesh);
        if (!EmbreeLibrary.TryLoad(out problem))
            return null;

        var config = Encoding.ASCII.GetBytes($"threads={threads}\0");
        nint device;
        fixed (byte* c = config)
            device = EmbreeLibrary.NewDevice(c);
        if (device == 0)
        {
            problem = "rtcNewDevice failed";
            return null;
        }

        var scene = TryBuild(device, mesh, out problem);
        if (scene == 0)
        {
            EmbreeLibrary.ReleaseDevice(device);
            return null;
        }

        return new EmbreeScene(device, scene, ownsDevice: true);
    }

    /// <summary>
    /// Builds another scene on this one's device, whose threads are already running: what a build costs
    /// once the library is started, as our builds run on a thread pool that is already started. This
    /// scene must outlive the new one.
    /// </summary>
    public EmbreeScene? TryCreateOnSameDevice(Mesh mesh, out string? problem)
    {
        ArgumentNullException.ThrowIfNull(mesh);
        ObjectDisposedException.ThrowIf(_device == 0, this);
        var scene = TryBuild(_device, mesh, out problem);
        return scene == 0 ? null : new EmbreeScene(_device, scene, ownsDevice: false);
    }

    /// <summary>A committed scene holding the mesh, or 0 with the reason.</summary>
    private static nint TryBuild(nint device, Mesh mesh, out string? problem)
    {
        var scene = EmbreeLibrary.NewScene(device);
        var geometry = EmbreeLibrary.NewGeometry(device, EmbreeLibrary.GeometryTypeTriangle);
        var vertices = mesh.Vertices;
        var indices = mesh.Indices;
        var v = (float*)EmbreeLibrary.SetNewGeometryBuffer(geometry, EmbreeLibrary.BufferTypeVertex, 0,
            EmbreeLibrary.FormatFloat3, 3 * sizeof(float), (nuint)vertices.Length);
        var ix = (uint*)EmbreeLibrary.SetNewGeometryBuffer(geometry, EmbreeLibrary.BufferTypeIndex, 0,
            EmbreeLibrary.FormatUInt3, 3 * sizeof(uint), (nuint)(indices.Length / 3));
        if (v == null || ix == null)
        {
            problem = $"rtcSetNewGeometryBuffer failed (error {EmbreeLibrary.GetDeviceError(device)})";
            EmbreeLibrary.ReleaseGeometry(geometry);
            EmbreeLibrary.ReleaseScene(scene);
            return 0;
        }

        for (int i = 0; i < vertices.Length; i++)
        {
            v[3 * i] = (float)vertices[i].x;
            v[3 * i + 1] = (float)vertices[i].y;
            v[3 * i + 2] = (float)vertices[i].z;
        }

        for (int i = 0; i < indices.Length - indices.Length % 3; i++)
            ix[i] = (uint)indices[i];

        EmbreeLibrary.CommitGeometry(geometry);
        EmbreeLibrary.AttachGeometry(scene, geometry);
        EmbreeLibrary.ReleaseGeometry(geometry); // the scene holds it now
        EmbreeLibrary.CommitScene(scene);
        int error = EmbreeLibrary.GetDeviceError(device);
        if (error != 0)
        {
            problem = $"building the Embree scene failed (RTCError {error})";
            EmbreeLibrary.ReleaseScene(scene);
            return 0;
        }

        problem = null;
        return scene;
    }

    /// <summary>Nearest hit with t in (ray.tMin, <paramref name="tMax"/>): its distance and triangle index (as in the mesh).</summary>
    [SkipLocalsInit]
    public bool IntersectNearest(in Ray ray, double tMax, out double t, out int primitive)
    {
        // Embree reads the ray with aligned vector loads: place it on a 16-byte boundary.
        byte* raw = stackalloc byte[sizeof(EmbreeRayHit) + 16];
        var rayHit = (EmbreeRayHit*)(((nint)raw + 15) & ~(nint)15);
        Fill(ref rayHit->Ray, ray, tMax);
        rayHit->Hit.GeomId = EmbreeLibrary.InvalidGeometryId;
        rayHit->Hit.InstId0 = EmbreeLibrary.InvalidGeometryId;
        var context = EmbreeIntersectContext.Incoherent;
        EmbreeLibrary.Intersect1(_scene, &context, rayHit);
        if (rayHit->Hit.GeomId == EmbreeLibrary.InvalidGeometryId)
        {
            t = 0;
            primitive = -1;
            return false;
        }

        t = rayHit->Ray.TFar;
        primitive = (int)rayHit->Hit.PrimId;
        return true;
    }

    /// <summary>Whether anything is hit with t in (ray.tMin, <paramref name="tMax"/>).</summary>
    [SkipLocalsInit]
    public bool IntersectAny(in Ray ray, double tMax)
    {
        byte* raw = stackalloc byte[sizeof(EmbreeRay) + 16];
        var r = (EmbreeRay*)(((nint)raw + 15) & ~(nint)15);
        Fill(ref *r, ray, tMax);
        var context = EmbreeIntersectContext.Incoherent;
        EmbreeLibrary.Occluded1(_scene, &context, r);
        return r->TFar < 0; // Embree sets tfar to −∞ on a hit
    }

    /// <summary>Casts up to 8 rays as one packet with <c>rtcIntersect8</c>; bit i of the result is set when ray i hits something below <paramref name="tMax"/>.</summary>
    [SkipLocalsInit]
    public int IntersectNearest8(ReadOnlySpan<Ray> rays, double tMax)
    {
        ArgumentOutOfRangeException.ThrowIfGreaterThan(rays.Length, 8);
        // Packet and valid mask are read with 32-byte vector loads.
        byte* raw = stackalloc byte[sizeof(EmbreeRayHit8) + 32 + 32];
        var packet = (EmbreeRayHit8*)(((nint)raw + 31) & ~(nint)31);
        var valid = (int*)(packet + 1);
        for (int i = 0; i < 8; i++)
        {
            valid[i] = i < rays.Length ? -1 : 0;
            Fill(ref packet->Ray, i, i < rays.Length ? rays[i] : default, tMax);
            packet->Hit.GeomId[i] = EmbreeLibrary.InvalidGeometryId;
            packet->Hit.InstId0[i] = EmbreeLibrary.InvalidGeometryId;
        }

        var context = EmbreeIntersectContext.Coherent;
        EmbreeLibrary.Intersect8(valid, _scene, &context, packet);
        int hits = 0;
        for (int i = 0; i < rays.Length; i++)
        {
            if (packet->Hit.GeomId[i] != EmbreeLibrary.InvalidGeometryId)
                hits |= 1 << i;
        }

        return hits;
    }

    /// <summary>Casts up to 8 rays as one packet with <c>rtcOccluded8</c>; bit i of the result is set when ray i is occluded below <paramref name="tMax"/>.</summary>
    [SkipLocalsInit]
    public int IntersectAny8(ReadOnlySpan<Ray> rays, double tMax)
    {
        ArgumentOutOfRangeException.ThrowIfGreaterThan(rays.Length, 8);
        byte* raw = stackalloc byte[sizeof(EmbreeRay8) + 32 + 32];
        var packet = (EmbreeRay8*)(((nint)raw + 31) & ~(nint)31);
        var valid = (int*)(packet + 1);
        for (int i = 0; i < 8; i++)
        {
            valid[i] = i < rays.Length ? -1 : 0;
            Fill(ref *packet, i, i < rays.Length ? rays[i] : default, tMax);
        }

        var context = EmbreeIntersectContext.Coherent;
        EmbreeLibrary.Occluded8(valid, _scene, &context, packet);
        int occluded = 0;
        for (int i = 0; i < rays.Length; i++)
        {
            if (packet->TFar[i] < 0)
                occluded |= 1 << i;
        }

        return occluded;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Fill(ref EmbreeRay8 target, int lane, in Ray ray, double tMax)
    {
        target.OrgX[lane] = (float)ray.o.x;
        target.OrgY[lane] = (float)ray.o.y;
        target.OrgZ[lane] = (float)ray.o.z;
        target.TNear[lane] = (float)ray.tMin;
        target.DirX[lane] = (float)ray.d.x;
        target.DirY[lane] = (float)ray.d.y;
        target.DirZ[lane] = (float)ray.d.z;
        target.Time[lane] = 0;
        target.TFar[lane] = (float)tMax;
        target.Mask[lane] = uint.MaxValue;
        target.Id[lane] = (uint)lane;
        target.Flags[lane] = 0;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Fill(ref EmbreeRay target, in Ray ray, double tMax)
    {
        target.OrgX = (float)ray.o.x;
        target.OrgY = (float)ray.o.y;
        target.OrgZ = (float)ray.o.z;
        target.TNear = (float)ray.tMin;
        target.DirX = (float)ray.d.x;
        target.DirY = (float)ray.d.y;
        target.DirZ = (float)ray.d.z;
        target.Time = 0;
        target.TFar = (float)tMax;
        target.Mask = uint.MaxValue;
        target.Id = 0;
        target.Flags = 0;
    }

    public void Dispose()
    {
        if (_scene != 0)
        {
            EmbreeLibrary.ReleaseScene(_scene);
            _scene = 0;
        }

        if (_device != 0 && _ownsDevice)
            EmbreeLibrary.ReleaseDevice(_device);
        _device = 0;
    }
}
