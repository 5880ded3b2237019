using RayTracer.Maths;

namespace RayTracer.Tests.Layout;

public class Namespaces_ByConcept
{
    [Fact]
    public void Util_namespace_holds_nothing_but_the_atomic_file_writer()
    {
        // Value types, transforms, bounds, randomness and shading state each have their own namespace;
        // only the file writer (about to leave the project) may remain under Util.
        var leftovers = typeof(Vector3D).Assembly.GetTypes()
            .Where(t => t.Namespace == "RayTracer.Util" && !t.IsNested && !t.Name.StartsWith('<'))
            .Select(t => t.Name)
            .Where(name => name != "AtomicFile")
            .ToList();
        Assert.Empty(leftovers);
    }
}
