using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;

namespace RayTracer.Geometry.Compound;

/// <summary>
/// Solid cylinder about the y axis whose rim edges are rounded with the given bevel radius:
/// two disks, a shortened tube and two tori sitting in the corners.
/// </summary>
public sealed class BeveledCylinder : CompoundObject
{
    public BeveledCylinder(double bottom, double top, double radius, double bevelRadius)
    {
        if (!(bevelRadius > 0) || 2 * bevelRadius > top - bottom || bevelRadius >= radius)
        {
            throw new ArgumentException("The bevel radius must be positive, below the radius and at most half the height.");
        }

        double inner = radius - bevelRadius;
        Add(new Disk(new Point3D(0, bottom, 0), new Normal3D(0, -1, 0), inner));
        Add(new Disk(new Point3D(0, top, 0), new Normal3D(0, 1, 0), inner));
        if (top - bottom > 2 * bevelRadius)
        {
            Add(new OpenCylinder(bottom + bevelRadius, top - bevelRadius, radius) { NormalFacesRay = false });
        }

        Add(new Instance(new Torus(inner, bevelRadius)).Translate(0, bottom + bevelRadius, 0));
        Add(new Instance(new Torus(inner, bevelRadius)).Translate(0, top - bevelRadius, 0));
    }
}
