using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>
/// Prints a code block as C# for one kind of scalar code: plain <c>double</c>/<c>float</c>
/// (<see cref="CSharpScalarEmitter"/>) now, vector types beside it later, each its own emitter.
/// </summary>
public interface ICodeEmitter
{
    /// <summary>The scalar types (as a <c>//GMac.Type</c> line or <c>--scalar</c> names them) this emitter writes.</summary>
    IReadOnlyList<string> ScalarTypes { get; }

    string Emit(CodeBlock block, CSharpEmitOptions options);
}
