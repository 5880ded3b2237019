using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Instancing;

/// <summary>
/// Any object placed by a rotation, a uniform scale and a translation (thesis §6.6.1, TSR
/// instancing): twelve coefficients instead of the two 4×4 matrices of <see cref="Instance"/>. The
/// ray is taken into the object's frame and the normal back to the world by generated kernels; the
/// local direction is not renormalized, so t is the same on both rays.
/// </summary>
public sealed class TsrInstance : TransformedObject
{
    private readonly TsrTransform _tsr;

    /// <summary>The object moved as the frame of reference was moved from rest (e1, e2, the origin).</summary>
    public TsrInstance(GeometricObject target, FrameOfReference frame)
        : this(target, TsrTransform.FromFrame(frame))
    {
    }

    public TsrInstance(GeometricObject target, TsrTransform transform)
        : base(target)
    {
        _tsr = transform;
    }

    public TsrTransform Transform => _tsr;

    protected override Normal3D NormalToWorld(Normal3D n)
    {
        var world = new Normal3D();

        #region GMac : TsrNormalToWorld
        //GMac.Bind("axis.e1", "<_tsr.kx>");
        //GMac.Bind("axis.e2", "<_tsr.ky>");
        //GMac.Bind("axis.e3", "<_tsr.kz>");
        //GMac.Bind("c.1", "<_tsr.cosOverScale>");
        //GMac.Bind("sn.1", "<_tsr.sinOverScale>");
        //GMac.Bind("vs.1", "<_tsr.versineOverScale>");
        //GMac.Bind("s.1", "<_tsr.scale>");
        //GMac.Bind("n", "Normal3D", n);
        //GMac.Bind("nw", "Normal3D", world);
        double tmp0 = _tsr.versineOverScale * (_tsr.kx * n.x + _tsr.ky * n.y + _tsr.kz * n.z);
        world.x = _tsr.scale * (_tsr.sinOverScale * (_tsr.ky * n.z - _tsr.kz * n.y) + tmp0 * _tsr.kx + _tsr.cosOverScale * n.x);
        world.y = _tsr.scale * (_tsr.sinOverScale * (_tsr.kz * n.x - _tsr.kx * n.z) + tmp0 * _tsr.ky + _tsr.cosOverScale * n.y);
        world.z = _tsr.scale * (_tsr.sinOverScale * (_tsr.kx * n.y - _tsr.ky * n.x) + tmp0 * _tsr.kz + _tsr.cosOverScale * n.z);
        #endregion

        return world;
    }

    public override BoundingBox GetBoundingBox()
    {
        var box = Target.GetBoundingBox().Map(_tsr.ToWorld);
        return box.IsEmpty || !box.IsFinite ? box : box.Expanded(Tolerances.BoundsPadding * (1 + _tsr.scale));
    }

    protected override Ray ToLocal(in Ray ray)
    {
        // The map keeps t (the direction is not renormalised), so the nearest distance accepted carries over.
        var local = new Ray { tMin = ray.tMin };

        #region GMac : TsrInverseRay
        //GMac.Bind("translation.e1", "<_tsr.tx>");
        //GMac.Bind("translation.e2", "<_tsr.ty>");
        //GMac.Bind("translation.e3", "<_tsr.tz>");
        //GMac.Bind("axis.e1", "<_tsr.kx>");
        //GMac.Bind("axis.e2", "<_tsr.ky>");
        //GMac.Bind("axis.e3", "<_tsr.kz>");
        //GMac.Bind("c.1", "<_tsr.cosOverScale>");
        //GMac.Bind("sn.1", "<_tsr.sinOverScale>");
        //GMac.Bind("vs.1", "<_tsr.versineOverScale>");
        //GMac.Bind("o", "Point3D", ray.o);
        //GMac.Bind("d", "Vector3D", ray.d);
        //GMac.Bind("lo", "Point3D", local.o);
        //GMac.Bind("ld", "Vector3D", local.d);
        double tmp0 = ray.o.x - _tsr.tx;
        double tmp1 = ray.o.y - _tsr.ty;
        double tmp2 = ray.o.z - _tsr.tz;
        double tmp3 = _tsr.versineOverScale * (tmp0 * _tsr.kx + tmp1 * _tsr.ky + tmp2 * _tsr.kz);
        double tmp4 = _tsr.versineOverScale * (ray.d.x * _tsr.kx + ray.d.y * _tsr.ky + ray.d.z * _tsr.kz);
        local.o.x = _tsr.sinOverScale * (tmp1 * _tsr.kz - tmp2 * _tsr.ky) + tmp0 * _tsr.cosOverScale + tmp3 * _tsr.kx;
        local.o.y = _tsr.sinOverScale * (tmp2 * _tsr.kx - tmp0 * _tsr.kz) + tmp1 * _tsr.cosOverScale + tmp3 * _tsr.ky;
        local.o.z = _tsr.sinOverScale * (tmp0 * _tsr.ky - tmp1 * _tsr.kx) + tmp3 * _tsr.kz + tmp2 * _tsr.cosOverScale;
        local.d.x = _tsr.sinOverScale * (ray.d.y * _tsr.kz - ray.d.z * _tsr.ky) + tmp4 * _tsr.kx + ray.d.x * _tsr.cosOverScale;
        local.d.y = _tsr.sinOverScale * (ray.d.z * _tsr.kx - ray.d.x * _tsr.kz) + tmp4 * _tsr.ky + ray.d.y * _tsr.cosOverScale;
        local.d.z = _tsr.sinOverScale * (ray.d.x * _tsr.ky - ray.d.y * _tsr.kx) + tmp4 * _tsr.kz + ray.d.z * _tsr.cosOverScale;
        #endregion

        return local;
    }
}
