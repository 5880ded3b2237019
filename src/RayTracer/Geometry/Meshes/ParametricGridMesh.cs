using RayTracer.Maths;
using Twister;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// A surface sampled on a regular (u, v) grid, each sample pushed along the unit normal by a height
/// field: uSteps · vSteps · 2 triangles, an exact count where adaptive tessellation gives whatever the
/// tolerance asks. Vertex normals are recomputed from the displaced triangles.
/// </summary>
public static class ParametricGridMesh
{
    public static Mesh Create(IParametricSurface surface, int uSteps, int vSteps, Func<double, double, double>? height = null)
    {
        ArgumentNullException.ThrowIfNull(surface);
        ArgumentOutOfRangeException.ThrowIfLessThan(uSteps, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(vSteps, 1);
        var vertices = new Point3D[(uSteps + 1) * (vSteps + 1)];
        for (var j = 0; j <= vSteps; j++)
        {
            for (var i = 0; i <= uSteps; i++)
            {
                double u = (double)i / uSteps, v = (double)j / vSteps;
                var p = surface.PointAt(u, v);
                var point = new Point3D(p.x, p.y, p.z);
                if (height is not null)
                {
                    var n = surface.NormalAt(u, v);
                    var normal = new Vector3D(n.x, n.y, n.z);
                    var length = normal.Length;
                    if (length > 0)
                        point += height(u, v) / length * normal;
                }

                vertices[j * (uSteps + 1) + i] = point;
            }
        }

        var indices = new int[6 * uSteps * vSteps];
        var k = 0;
        for (var j = 0; j < vSteps; j++)
        {
            for (var i = 0; i < uSteps; i++)
            {
                int a = j * (uSteps + 1) + i, b = a + 1, c = a + uSteps + 1, d = c + 1;
                foreach (var corner in (ReadOnlySpan<int>)[a, b, d, a, d, c])
                    indices[k++] = corner;
            }
        }

        var mesh = new Mesh(vertices, indices);
        mesh.ComputeVertexNormals();
        return mesh;
    }
}
