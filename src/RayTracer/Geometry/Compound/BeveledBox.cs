using RayTracer.Geometry.Universal;
using RayTracer.Maths;

namespace RayTracer.Geometry.Compound;

/// <summary>
/// Axis-aligned solid box with edges rounded by the bevel radius: six face rectangles inset by the
/// radius, twelve edge cylinders and eight corner spheres.
/// </summary>
public sealed class BeveledBox : CompoundObject
{
    public BeveledBox(Point3D p0, Point3D p1, double bevelRadius)
    {
        Point3D lo = Point3D.Min(p0, p1), hi = Point3D.Max(p0, p1);
        var size = hi - lo;
        double rb = bevelRadius;
        if (!(rb > 0) || 2 * rb >= Math.Min(size.x, Math.Min(size.y, size.z)))
        {
            throw new ArgumentException("The bevel radius must be positive and below half the smallest side.");
        }

        // Inner box whose Minkowski sum with a ball of radius rb is the beveled box.
        Point3D a = lo + new Vector3D(rb), b = hi - new Vector3D(rb);
        double wx = b.x - a.x, wy = b.y - a.y, wz = b.z - a.z;

        for (int i = 0; i < 8; i++)
        {
            Add(new Sphere(new Point3D((i & 1) == 0 ? a.x : b.x, (i & 2) == 0 ? a.y : b.y, (i & 4) == 0 ? a.z : b.z), rb));
        }

        for (int i = 0; i < 4; i++)
        {
            double u = (i & 1) == 0 ? 0 : 1, v = (i & 2) == 0 ? 0 : 1;
            AddEdge(new Point3D(a.x, a.y + u * wy, a.z + v * wz), new Vector3D(wx, 0, 0), rb);
            AddEdge(new Point3D(a.x + u * wx, a.y, a.z + v * wz), new Vector3D(0, wy, 0), rb);
            AddEdge(new Point3D(a.x + u * wx, a.y + v * wy, a.z), new Vector3D(0, 0, wz), rb);
        }

        var ex = new Vector3D(wx, 0, 0);
        var ey = new Vector3D(0, wy, 0);
        var ez = new Vector3D(0, 0, wz);
        Add(new Rectangle(new Point3D(lo.x, a.y, a.z), ey, ez, new Normal3D(-1, 0, 0)));
        Add(new Rectangle(new Point3D(hi.x, a.y, a.z), ey, ez, new Normal3D(1, 0, 0)));
        Add(new Rectangle(new Point3D(a.x, lo.y, a.z), ex, ez, new Normal3D(0, -1, 0)));
        Add(new Rectangle(new Point3D(a.x, hi.y, a.z), ex, ez, new Normal3D(0, 1, 0)));
        Add(new Rectangle(new Point3D(a.x, a.y, lo.z), ex, ey, new Normal3D(0, 0, -1)));
        Add(new Rectangle(new Point3D(a.x, a.y, hi.z), ex, ey, new Normal3D(0, 0, 1)));
    }

    private void AddEdge(Point3D start, Vector3D axis, double radius)
    {
        if (axis.LengthSquared > 0)
        {
            Add(new Cylinder(start, axis, radius) { NormalFacesRay = false });
        }
    }
}
