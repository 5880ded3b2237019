using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Csg;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Primitives;

/// <summary>
/// Constructive solids: a box with a spherical bite, a sphere–cube intersection, and two fused spheres
/// drilled by a cylinder. Operands keep their own materials, so cut faces show the solid that cut them.
/// </summary>
public sealed class ConstructiveSolidsScene : SceneDescription
{
    public override string Name => "primitives-csg";
    public override string Description => "Constructive solid geometry: difference, intersection and nested union-minus-cylinder.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.1, 0.11, 0.14);
        world.AmbientLight = new AmbientLight(0.4);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.72, 0.72, 0.7)) });

        var orange = MaterialFactory.Plastic(new RGBColor(0.9, 0.5, 0.15));
        var blue = MaterialFactory.Plastic(new RGBColor(0.2, 0.45, 0.9));
        var green = MaterialFactory.Plastic(new RGBColor(0.3, 0.8, 0.35));
        var purple = MaterialFactory.Plastic(new RGBColor(0.65, 0.3, 0.8));
        var red = MaterialFactory.Plastic(new RGBColor(0.85, 0.2, 0.2));

        var bitten = new ConstructiveSolid(SolidOperation.Difference,
            new Box(new Point3D(-3.6, 0, -0.7), new Point3D(-2.2, 1.4, 0.7)) { Material = orange },
            new Sphere(new Point3D(-2.2, 1.4, 0.7), 0.8) { Material = blue });
        world.Add(bitten);

        var roundedCube = new ConstructiveSolid(SolidOperation.Intersection,
            new Box(new Point3D(-0.75, 0, -0.75), new Point3D(0.75, 1.5, 0.75)) { Material = green },
            new Sphere(new Point3D(0, 0.75, 0), 0.98) { Material = purple });
        world.Add(WithInstance(roundedCube, 0.6));

        var fused = new ConstructiveSolid(SolidOperation.Union,
            new Sphere(new Point3D(2.4, 0.8, 0), 0.8) { Material = red },
            new Sphere(new Point3D(3.2, 0.8, -0.3), 0.7) { Material = red });
        var drill = new Instance(new SolidCylinder(-1.5, 1.5, 0.3)).RotateX(Math.PI / 2).Translate(2.7, 0.8, 0);
        drill.Material = blue;
        world.Add(new ConstructiveSolid(SolidOperation.Difference, fused, drill));

        world.Add(LightFactory.Point(new Point3D(-3, 7, 7), 1.3));
        world.Add(LightFactory.Directional(new Vector3D(3, 4, 2), 0.45));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 3.2, 8), new Point3D(0, 0.7, 0), 55, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }

    private static Instance WithInstance(GeometricObject solid, double turn) => new Instance(solid).RotateY(turn);
}
