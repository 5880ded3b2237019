namespace RayTracer.Geometry.Csg;

/// <summary>Boolean operation combining two solids.</summary>
public enum SolidOperation
{
    /// <summary>Points in either solid.</summary>
    Union,

    /// <summary>Points in both solids.</summary>
    Intersection,

    /// <summary>Points in the first solid but not in the second.</summary>
    Difference,
}
