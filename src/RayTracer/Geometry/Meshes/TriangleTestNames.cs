namespace RayTracer.Geometry.Meshes;

/// <summary>The command-line names of the <see cref="TriangleTest"/> values.</summary>
public static class TriangleTestNames
{
    public static IReadOnlyList<string> All { get; } = ["moller", "algebraic", "plucker", "plucker-edges"];

    public static string Name(this TriangleTest test) => test switch
    {
        TriangleTest.MollerTrumbore => "moller",
        TriangleTest.Algebraic => "algebraic",
        TriangleTest.Plucker => "plucker",
        TriangleTest.PluckerEdges => "plucker-edges",
        _ => throw new ArgumentOutOfRangeException(nameof(test)),
    };

    public static bool TryParse(string? name, out TriangleTest test)
    {
        foreach (var candidate in Enum.GetValues<TriangleTest>())
        {
            if (string.Equals(candidate.Name(), name, StringComparison.OrdinalIgnoreCase))
            {
                test = candidate;
                return true;
            }
        }

        test = default;
        return false;
    }
}
