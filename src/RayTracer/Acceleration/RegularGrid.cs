using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// Uniform grid over the scene bounds (Suffern, ch. 22). The cell count is chosen so that there are
/// about multiplier³ cells per object: with s = ∛(wx wy wz / n), each axis gets ⌊m w / s⌋ + 1 cells.
/// Cells list the objects whose boxes overlap them (stored compactly as offsets into one index
/// array); rays walk the cells in order with a 3D DDA and stop at the first cell whose nearest hit
/// lies inside that cell.
/// </summary>
public sealed class RegularGrid : AccelerationStructure
{
    private const long MaxCells = 64L << 20;

    private readonly int _nx, _ny, _nz;
    private readonly BoundingBox _box;
    private readonly int[] _cellStart = [];
    private readonly int[] _cellObjects = [];

    public RegularGrid(IReadOnlyList<GeometricObject> objects, double multiplier = 2.0)
        : base(objects)
    {
        if (!(multiplier > 0))
        {
            throw new ArgumentOutOfRangeException(nameof(multiplier), "The grid multiplier must be positive.");
        }

        int n = Table.Count;
        if (n == 0)
        {
            return;
        }

        // Pad so that flat scenes (all objects in one plane) still get a box with volume.
        var size = Table.SceneBounds.Diagonal;
        double pad = 1e-6 * Math.Max(1e-6, Math.Max(size.x, Math.Max(size.y, size.z)));
        _box = Table.SceneBounds.Expanded(pad);
        size = _box.Diagonal;

        double s = Math.Cbrt(size.x * size.y * size.z / n);
        _nx = (int)Math.Min(1024, multiplier * size.x / s) + 1;
        _ny = (int)Math.Min(1024, multiplier * size.y / s) + 1;
        _nz = (int)Math.Min(1024, multiplier * size.z / s) + 1;
        while ((long)_nx * _ny * _nz > MaxCells)
        {
            _nx = Math.Max(1, _nx / 2);
            _ny = Math.Max(1, _ny / 2);
            _nz = Math.Max(1, _nz / 2);
        }

        int cells = _nx * _ny * _nz;
        var counts = new int[cells + 1];
        for (int pass = 0; pass < 2; pass++)
        {
            var cursor = pass == 1 ? (int[])_cellStart.Clone() : counts;
            for (int i = 0; i < n; i++)
            {
                var b = Table.Bounds[i];
                int x0 = CellX(b.Min.x), x1 = CellX(b.Max.x);
                int y0 = CellY(b.Min.y), y1 = CellY(b.Max.y);
                int z0 = CellZ(b.Min.z), z1 = CellZ(b.Max.z);
                for (int z = z0; z <= z1; z++)
                {
                    for (int y = y0; y <= y1; y++)
                    {
                        for (int x = x0; x <= x1; x++)
                        {
                            int cell = x + _nx * (y + _ny * z);
                            if (pass == 0)
                            {
                                counts[cell + 1]++;
                            }
                            else
                            {
                                _cellObjects[cursor[cell]++] = i;
                            }
                        }
                    }
                }
            }

            if (pass == 0)
            {
                for (int c = 0; c < cells; c++)
                {
                    counts[c + 1] += counts[c];
                }

                _cellStart = counts;
                _cellObjects = new int[counts[cells]];
            }
        }

        Table.ReleaseBuildData();
        Table.PackTriangles();
    }

    private protected override bool TraverseNearest(in Ray ray, ref double t, ref int primitive)
    {
        double limit = t;
        bool hit = false;
        int best = primitive;
        double tBest = t;
        bool found = Walk(ray, limit, nearest: true, ref tBest, ref best, ref hit);
        if (found)
        {
            t = tBest;
            primitive = best;
        }

        return found;
    }

    private protected override bool TraverseAny(in Ray ray, double tMax)
    {
        double t = tMax;
        int best = -1;
        bool hit = false;
        return Walk(ray, tMax, nearest: false, ref t, ref best, ref hit);
    }

    private bool Walk(in Ray ray, double tMax, bool nearest, ref double tBest, ref int best, ref bool hit)
    {
        var inv = new Vector3D(1.0 / ray.d.x, 1.0 / ray.d.y, 1.0 / ray.d.z);
        if (!_box.Intersect(ray.o, inv, 0, tMax, out double tEnter, out double tExit))
        {
            return false;
        }

        var start = ray.At(tEnter);
        int ix = CellX(start.x), iy = CellY(start.y), iz = CellZ(start.z);
        Axis(ray.o.x, ray.d.x, inv.x, _box.Min.x, _box.Max.x, _nx, ix, out double nextX, out double dtx, out int stepX, out int stopX);
        Axis(ray.o.y, ray.d.y, inv.y, _box.Min.y, _box.Max.y, _ny, iy, out double nextY, out double dty, out int stepY, out int stopY);
        Axis(ray.o.z, ray.d.z, inv.z, _box.Min.z, _box.Max.z, _nz, iz, out double nextZ, out double dtz, out int stepZ, out int stopZ);
        var table = Table;

        while (true)
        {
            // The cell is left at the smallest of the three next crossings.
            double cellExit = Math.Min(nextX, Math.Min(nextY, nextZ));
            int cell = ix + _nx * (iy + _ny * iz);
            int end = _cellStart[cell + 1];
            for (int k = _cellStart[cell]; k < end; k++)
            {
                int i = _cellObjects[k];
                if (nearest)
                {
                    double ti = table.Distance(i, ray, tBest);
                    if (ti < tBest)
                    {
                        tBest = ti;
                        best = i;
                        hit = true;
                    }
                }
                else if (table.Occludes(i, ray, tMax))
                {
                    return true;
                }
            }

            // An object spanning several cells may be hit beyond this cell; such a hit is only final
            // once the walk reaches the cell that contains it.
            if (hit && tBest <= cellExit)
            {
                return true;
            }

            if (cellExit > Math.Min(tExit, tBest))
            {
                return hit;
            }

            if (nextX <= nextY && nextX <= nextZ)
            {
                ix += stepX;
                if (ix == stopX)
                {
                    return hit;
                }

                nextX += dtx;
            }
            else if (nextY <= nextZ)
            {
                iy += stepY;
                if (iy == stopY)
                {
                    return hit;
                }

                nextY += dty;
            }
            else
            {
                iz += stepZ;
                if (iz == stopZ)
                {
                    return hit;
                }

                nextZ += dtz;
            }
        }
    }

    /// <summary>DDA set-up along one axis: parameter of the next cell boundary, its increment, step and stop index.</summary>
    private static void Axis(double o, double d, double inv, double lo, double hi, int cells, int index,
        out double next, out double dt, out int step, out int stop)
    {
        if (d > 0)
        {
            double t0 = (lo - o) * inv, t1 = (hi - o) * inv;
            dt = (t1 - t0) / cells;
            next = t0 + (index + 1) * dt;
            step = 1;
            stop = cells;
        }
        else if (d < 0)
        {
            double t0 = (hi - o) * inv, t1 = (lo - o) * inv;
            dt = (t1 - t0) / cells;
            next = t0 + (cells - index) * dt;
            step = -1;
            stop = -1;
        }
        else
        {
            dt = 0;
            next = double.PositiveInfinity;
            step = -1;
            stop = -1;
        }
    }

    private int CellX(double x) => Math.Clamp((int)((x - _box.Min.x) * _nx / (_box.Max.x - _box.Min.x)), 0, _nx - 1);

    private int CellY(double y) => Math.Clamp((int)((y - _box.Min.y) * _ny / (_box.Max.y - _box.Min.y)), 0, _ny - 1);

    private int CellZ(double z) => Math.Clamp((int)((z - _box.Min.z) * _nz / (_box.Max.z - _box.Min.z)), 0, _nz - 1);
}
