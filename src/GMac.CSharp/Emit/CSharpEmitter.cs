using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>The C# emitters, and the one that writes a block in the scalar type its options name.</summary>
public static partial class CSharpEmitter
{
    /// <summary>Every emitter; each scalar type is written by exactly one.</summary>
    public static IReadOnlyList<ICodeEmitter> Emitters { get; } = [CSharpScalarEmitter.Instance];

    /// <summary>The scalar types gmac writes, in the emitters' order (the first is the default).</summary>
    public static IReadOnlyList<string> ScalarTypes { get; } = Emitters.SelectMany(e => e.ScalarTypes).ToList();

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
