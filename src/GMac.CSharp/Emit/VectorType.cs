namespace GMac.CSharp.Emit;

/// <summary>
/// A SIMD type gmac writes code in: <c>Vector128/256/512&lt;T&gt;</c> (System.Runtime.Intrinsics) or
/// <c>Vector&lt;T&gt;</c> (System.Numerics), over <c>float</c> or <c>double</c>.
/// </summary>
/// <param name="Family">The static class of the type's functions: <c>Vector256</c>, or <c>Vector</c> for <c>Vector&lt;T&gt;</c>.</param>
/// <param name="Element">The lane type, <c>double</c> or <c>float</c>.</param>
internal sealed record VectorType(string Family, string Element)
{
    public static IReadOnlyList<VectorType> All { get; } =
        [.. new[] { "Vector128", "Vector256", "Vector512", "Vector" }.SelectMany(f => new[] { new VectorType(f, "double"), new VectorType(f, "float") })];

    /// <summary>The C# type, as <c>//GMac.Type</c> and <c>--scalar</c> name it.</summary>
    public string Name => $"{Family}<{Element}>";

    public bool IsSingle => Element == "float";

    /// <summary>Whether the number of lanes is fixed in C# (not <c>Vector&lt;T&gt;</c>, whose width the machine decides).</summary>
    public bool HasFixedWidth => Family != "Vector";

    /// <summary>Lanes on the running machine.</summary>
    public int Lanes => Family switch
    {
        "Vector128" => 16,
        "Vector256" => 32,
        "Vector512" => 64,
        _ => System.Numerics.Vector<byte>.Count,
    } / (IsSingle ? sizeof(float) : sizeof(double));

    /// <summary>The namespace the file needs a <c>using</c> for.</summary>
    public string Namespace => HasFixedWidth ? "System.Runtime.Intrinsics" : "System.Numerics";

    public static VectorType? Find(string scalarType) => All.FirstOrDefault(v => v.Name == scalarType);
}
