namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>The vector implementations of a kernel, each over the batch in columns (structure of arrays).</summary>
public enum VectorVariant
{
    /// <summary>A <c>//GMac.Batch</c> binding point generated in <c>Vector256&lt;double&gt;</c>.</summary>
    Generated256,

    /// <summary>The same binding point in <c>Vector512&lt;double&gt;</c>.</summary>
    Generated512,

    /// <summary>Vector code written by hand in <c>Vector256&lt;double&gt;</c> (four kernels).</summary>
    Hand256,
}
