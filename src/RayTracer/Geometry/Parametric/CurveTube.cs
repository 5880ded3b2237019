using RayTracer.Geometry.Universal;
using RayTracer.Materials;
using RayTracer.Maths;
using Twister;
using Twister.Tessellation;

namespace RayTracer.Geometry.Parametric;

/// <summary>
/// A parametric curve given a thickness (thesis §6.2.3): the curve is sampled adaptively, each
/// segment becomes a cylinder of the tube's radius and every sample a sphere of the same radius, so
/// the joints are round and the tube has no gaps; all of them go into one hierarchy.
/// </summary>
public sealed class CurveTube : AcceleratedGroup
{
    private readonly List<GeometricObject> _parts = [];

    /// <param name="tolerance">Largest distance between the curve and the tube's axis, in scene units.</param>
    public CurveTube(IParametricCurve curve, double radius, double tolerance)
        : this(curve, radius, new TessellationOptions(tolerance))
    {
    }

    public CurveTube(IParametricCurve curve, double radius, TessellationOptions options)
    {
        ArgumentNullException.ThrowIfNull(curve);
        if (!(radius > 0) || double.IsInfinity(radius))
        {
            throw new ArgumentOutOfRangeException(nameof(radius), radius, "A tube needs a positive finite radius.");
        }

        Radius = radius;
        Samples = CurveSampler.Sample(curve, options);
        Point3D? previous = null;
        foreach (var q in Samples.Points)
        {
            var p = new Point3D(q.x, q.y, q.z);
            if (previous is { } start)
            {
                var axis = p - start;
                if (axis.LengthSquared == 0)
                {
                    continue; // the curve paused: one sphere already covers the point
                }

                _parts.Add(new Cylinder(start, axis, radius) { NormalFacesRay = false });
            }

            _parts.Add(new Sphere(p, radius));
            previous = p;
        }

        Build(_parts);
    }

    public double Radius { get; }

    /// <summary>The curve's samples: the tube's joints.</summary>
    public Polyline Samples { get; }

    /// <summary>Setting the material gives it to every cylinder and sphere.</summary>
    public override Material? Material
    {
        get => base.Material;
        set
        {
            base.Material = value;
            foreach (var part in _parts)
            {
                part.Material = value;
            }
        }
    }
}
