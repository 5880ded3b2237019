using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;

namespace RayTracer.Geometry.Compound;

/// <summary>Closed cylinder about the y axis: tube plus bottom and top disks, all normals outward.</summary>
public sealed class SolidCylinder : CompoundObject
{
    public SolidCylinder(double bottom, double top, double radius)
    {
        Add(new Disk(new Point3D(0, bottom, 0), new Normal3D(0, -1, 0), radius));
        Add(new Disk(new Point3D(0, top, 0), new Normal3D(0, 1, 0), radius));
        Add(new OpenCylinder(bottom, top, radius) { NormalFacesRay = false });
    }
}
