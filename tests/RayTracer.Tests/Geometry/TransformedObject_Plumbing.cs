using RayTracer.Geometry;
using RayTracer.Geometry.Instancing;
using RayTracer.Geometry.Universal;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry;

public class TransformedObject_Plumbing
{
    private static readonly Matte TargetMaterial = new(), OverrideMaterial = new(0.1, 0.2);

    /// <summary>A unit sphere moved to (0, 0, 5) by each of the three placements.</summary>
    public static TheoryData<string> Placements() => ["affine", "tsr", "rstr"];

    private static TransformedObject Place(string kind)
    {
        var sphere = new Sphere(Point3D.Origin, 1) { Material = TargetMaterial };
        return kind switch
        {
            "affine" => new Instance(sphere).Translate(0, 0, 5),
            "tsr" => new TsrInstance(sphere, TsrTransform.FromParts(new Vector3D(0, 0, 5), Vector3D.UnitY, 0, 1)),
            _ => new RstrInstance(sphere, new Point3D(0, 0, 5), Vector3D.UnitY),
        };
    }

    [Theory]
    [MemberData(nameof(Placements))]
    public void Every_placement_hits_shadows_and_overrides_the_material_alike(string kind)
    {
        var placed = Place(kind);
        var ray = new Ray(Point3D.Origin, Vector3D.UnitZ);
        var sr = new ShadingRecord();
        Assert.True(placed.Hit(ray, out var t, sr));
        Assert.Equal(4.0, t, 12);
        Assert.Equal(-1.0, sr.Normal.z, 12);
        Assert.Same(TargetMaterial, placed.Material);
        Assert.True(placed.ShadowHit(ray, out _));

        placed.Material = OverrideMaterial;
        Assert.True(placed.Hit(ray, out _, sr));
        Assert.Same(OverrideMaterial, sr.Material);

        placed.CastsShadows = false;
        Assert.False(placed.ShadowHit(ray, out _));
        Assert.True(placed.Intersect(ray, out var ti));
        Assert.Equal(4.0, ti, 12);
    }
}
