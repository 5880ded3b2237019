using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Instancing;

/// <summary>
/// An object symmetric about its y axis (sphere, cylinder, cone, torus, disk) placed by a point
/// and a direction only (thesis §6.6.2, RSTR instancing): its origin goes to <see cref="Position"/>
/// and its y axis along <see cref="Direction"/>, with no scale. Any orthogonal map taking e2 onto
/// the direction places such an object alike, so the ray is taken back by the mirror −m x m that
/// takes the direction onto e2 (six coefficients: the point and m) rather than by a rotation.
/// Texture coordinates that depend on the azimuth come out mirrored; hits and normals do not.
/// The caller vouches for the symmetry: an object without it would be placed mirrored.
/// </summary>
public sealed class RstrInstance : TransformedObject
{
    private readonly double _px, _py, _pz;
    private readonly double _mx, _my, _mz;

    public RstrInstance(GeometricObject target, Point3D position, Vector3D direction)
        : base(target)
    {
        if (!double.IsFinite(position.x) || !double.IsFinite(position.y) || !double.IsFinite(position.z))
            throw new ArgumentException($"An RSTR instance needs a finite position, not {position}.", nameof(position));
        if (!double.IsFinite(direction.x) || !double.IsFinite(direction.y) || !double.IsFinite(direction.z))
            throw new ArgumentException($"An RSTR instance needs a finite direction, not {direction}.", nameof(direction));
        var length = direction.Length;
        if (!(length > 0))
            throw new ArgumentException("The axis direction of an RSTR instance must not be the zero vector.", nameof(direction));
        (_px, _py, _pz) = (position.x, position.y, position.z);
        var m = InstancingKernels.MirrorNormalOntoY(direction / length);
        (_mx, _my, _mz) = (m.x, m.y, m.z);
    }

    public Point3D Position => new(_px, _py, _pz);

    /// <summary>The unit direction the object's y axis is turned to: the mirror image of e2.</summary>
    public Vector3D Direction => MirrorLocal(Vector3D.UnitY);

    protected override Normal3D NormalToWorld(Normal3D n)
    {
        var world = new Normal3D();

        #region GMac : RstrNormalToWorld
        //GMac.Bind("m.e1", "<_mx>");
        //GMac.Bind("m.e2", "<_my>");
        //GMac.Bind("m.e3", "<_mz>");
        //GMac.Bind("n", "Normal3D", n);
        //GMac.Bind("nw", "Normal3D", world);
        double tmp0 = 2.0 * (_mx * n.x + _my * n.y + _mz * n.z);
        world.x = n.x - _mx * tmp0;
        world.y = n.y - _my * tmp0;
        world.z = n.z - _mz * tmp0;
        #endregion

        return world;
    }

    public override BoundingBox GetBoundingBox()
    {
        var box = Target.GetBoundingBox().Map(p =>
        {
            var moved = MirrorLocal(new Vector3D(p.x, p.y, p.z));
            return new Point3D(_px + moved.x, _py + moved.y, _pz + moved.z);
        });
        return box.IsEmpty || !box.IsFinite ? box : box.Expanded(Tolerances.BoundsPadding);
    }

    private Vector3D MirrorLocal(Vector3D x)
    {
        var twice = 2 * (x.x * _mx + x.y * _my + x.z * _mz);
        return new Vector3D(x.x - twice * _mx, x.y - twice * _my, x.z - twice * _mz);
    }

    protected override Ray ToLocal(in Ray ray)
    {
        // The map keeps t (the direction is not renormalised), so the nearest distance accepted carries over.
        var local = new Ray { tMin = ray.tMin };

        #region GMac : RstrInverseRay
        //GMac.Bind("p.e1", "<_px>");
        //GMac.Bind("p.e2", "<_py>");
        //GMac.Bind("p.e3", "<_pz>");
        //GMac.Bind("m.e1", "<_mx>");
        //GMac.Bind("m.e2", "<_my>");
        //GMac.Bind("m.e3", "<_mz>");
        //GMac.Bind("o", "Point3D", ray.o);
        //GMac.Bind("d", "Vector3D", ray.d);
        //GMac.Bind("lo", "Point3D", local.o);
        //GMac.Bind("ld", "Vector3D", local.d);
        double tmp0 = ray.o.x - _px;
        double tmp1 = ray.o.y - _py;
        double tmp2 = ray.o.z - _pz;
        double tmp3 = 2.0 * (tmp0 * _mx + tmp1 * _my + tmp2 * _mz);
        local.o.x = tmp0 - _mx * tmp3;
        local.o.y = tmp1 - _my * tmp3;
        local.o.z = tmp2 - _mz * tmp3;
        double tmp4 = 2.0 * (ray.d.y * _my + ray.d.z * _mz + _mx * ray.d.x);
        local.d.x = ray.d.x - _mx * tmp4;
        local.d.y = ray.d.y - _my * tmp4;
        local.d.z = ray.d.z - _mz * tmp4;
        #endregion

        return local;
    }
}
