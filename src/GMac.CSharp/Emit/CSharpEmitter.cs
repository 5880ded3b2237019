using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>The C# emitters, and the one that writes a block in the scalar type its options name.</summary>
public static partial class CSharpEmitter
{
    /// <summary>Every emitter; each scalar type is written by exactly one.</summary>
    public static IReadOnlyList<ICodeEmitter> Emitters { get; } = [CSharpScalarEmitter.Instance, CSharpVectorEmitter.Instance];

    /// <summary>The scalar types gmac writes, in the emitters' order (the first is the default).</summary>
    public static IReadOnlyList<string> ScalarTypes { get; } = Emitters.SelectMany(e => e.ScalarTypes).ToList();

    /// <summary>
    /// The scalar type as gmac spells it for a name given in any case (<c>Float</c>,
    /// <c>vector256&lt;double&gt;</c>), as MSBuild and the command line compare; null for none of them.
    /// </summary>
    public static string? ScalarTypeNamed(string name) => ScalarTypes.FirstOrDefault(t => string.Equals(t, name, StringComparison.OrdinalIgnoreCase));

    /// <summary>Whether the lanes of the scalar type are floats: <c>float</c>, <c>Vector256&lt;float&gt;</c>.</summary>
    public static bool IsSingle(string scalarType) => scalarType == "float" || VectorType.Find(scalarType) is { IsSingle: true };

    /// <summary>The emitter that writes <paramref name="scalarType"/>, or null when none does.</summary>
    public static ICodeEmitter? For(string scalarType) => Emitters.FirstOrDefault(e => e.ScalarTypes.Contains(scalarType));

    /// <exception cref="InvalidOperationException">No emitter writes the options' scalar type.</exception>
    public static string Emit(CodeBlock block, CSharpEmitOptions? options = null)
    {
        options ??= new CSharpEmitOptions();
        var emitter = For(options.ScalarType)
            ?? throw new InvalidOperationException($"No C# code for scalar type '{options.ScalarType}'; expected {string.Join(" or ", ScalarTypes)}.");
        return emitter.Emit(block, options);
    }
}
