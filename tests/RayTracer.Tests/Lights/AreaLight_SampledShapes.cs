using RayTracer.Geometry;
using RayTracer.Lights;

namespace RayTracer.Tests.Lights;

public class AreaLight_SampledShapes
{
    private static readonly string[] SamplingMembers = ["Sample", "Pdf", "GetNormal"];

    [Fact]
    public void Only_sampled_shapes_offer_light_sampling()
    {
        // An object that cannot be sampled must not have sampling members that fail at run time.
        var offenders = typeof(GeometricObject).Assembly.GetTypes()
            .Where(t => typeof(GeometricObject).IsAssignableFrom(t) && !typeof(ISampledShape).IsAssignableFrom(t))
            .SelectMany(t => t.GetMethods().Where(m => SamplingMembers.Contains(m.Name)).Select(m => $"{t.Name}.{m.Name}"))
            .ToList();
        Assert.Empty(offenders);
    }

    [Fact]
    public void Area_lights_are_built_only_on_sampled_shapes()
    {
        var shapeTypes = typeof(AreaLight).GetConstructors().Select(c => c.GetParameters()[0].ParameterType).Distinct();
        Assert.Equal([typeof(ISampledShape)], shapeTypes);
    }
}
