using RayTracer.Geometry;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Instancing;
using RayTracer.Geometry.Universal;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Transforms;
using Twister;

namespace RayTracer.Scenes.Instancing;

/// <summary>
/// An open tube from <paramref name="Base"/> along <paramref name="Axis"/> (direction and height)
/// of <paramref name="Radius"/>, which every <see cref="CylinderMethod"/> can build.
/// </summary>
public sealed record CylinderSpec(Point3D Base, Vector3D Axis, double Radius, Material? Material)
{
    /// <summary>The tube as <paramref name="method"/> places it, with the spec's material.</summary>
    public GeometricObject Create(CylinderMethod method)
    {
        var height = Axis.Length;
        GeometricObject tube = method switch
        {
            CylinderMethod.UCyl => new Cylinder(Base, Axis, Radius),
            CylinderMethod.GauCyl => new GaUniversalCylinder(Base, Axis, Radius),
            CylinderMethod.ICyl => new Instance(new OpenCylinder(0, height, Radius), MatrixPlacement()),
            CylinderMethod.TsrCyl => new TsrInstance(new OpenCylinder(0, height, Radius), FramePlacement()),
            CylinderMethod.RstrCyl => new RstrInstance(new OpenCylinder(0, height, Radius), Base, Axis),
            _ => throw new ArgumentOutOfRangeException(nameof(method), method, "unknown cylinder method"),
        };
        tube.Material = Material;
        return tube;
    }

    /// <summary>The rest frame turned (Twister) so e2 lies along the axis, then moved to the base.</summary>
    public FrameOfReference FramePlacement()
    {
        var (axis, angle) = TurnOfYOntoAxis();
        return FrameOfReference.Identity
            .Rotated(new TwistableVector(axis.x, axis.y, axis.z), angle)
            .Translated(new TwistableVector(Base.x, Base.y, Base.z));
    }

    /// <summary>The same placement as a 4×4 matrix: the rotation, then the translation.</summary>
    public AffineTransform MatrixPlacement()
    {
        var (axis, angle) = TurnOfYOntoAxis();
        return AffineTransform.Translation(Base.x, Base.y, Base.z) * AffineTransform.Rotation(axis, angle);
    }

    // The shortest turn taking e2 onto the axis; against e2 it is a half turn about e1.
    private (Vector3D Axis, double Angle) TurnOfYOntoAxis()
    {
        var unit = Axis.Normalized();
        var cross = Vector3D.Cross(Vector3D.UnitY, unit);
        var sin = cross.Length;
        if (sin < Tolerances.RelativeRounding)
            return unit.y > 0 ? (Vector3D.UnitX, 0) : (Vector3D.UnitX, Math.PI);
        return (cross / sin, Math.Atan2(sin, unit.y));
    }
}
