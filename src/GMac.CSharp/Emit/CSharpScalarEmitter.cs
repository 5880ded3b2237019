using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>
/// Prints a code block as C# statements on plain scalars (<c>double</c> or <c>float</c>), one
/// statement per assignment. Code over vector types is <see cref="CSharpVectorEmitter"/>.
/// </summary>
public sealed class CSharpScalarEmitter : CSharpBlockEmitter
{
    public static CSharpScalarEmitter Instance { get; } = new();

    private CSharpScalarEmitter()
    {
    }

    /// <summary><c>double</c> (the default) and <c>float</c>: with <c>float</c>, functions are <c>MathF</c>'s and constants <c>f</c>-suffixed literals rounded once to float.</summary>
    public override IReadOnlyList<string> ScalarTypes { get; } = ["double", "float"];

    protected override ValueWriter CreateWriter(CSharpEmitOptions options, Func<string, string> variableText, Func<string, string> freshName) =>
        new Writer(options.ScalarType == "float", variableText);

    private sealed class Writer(bool single, Func<string, string> variableText) : ValueWriter
    {
        public override string Print(Expr e) => single
            ? ExprPrinter.Print(e, variableText, f => ScalarFunction(f, single: true), SingleLiteral.Of)
            : ExprPrinter.Print(e, variableText, f => ScalarFunction(f, single: false));

        public override string SinCos(Expr argument) => (single ? "MathF" : "Math") + ".SinCos(" + Print(argument) + ")";
    }
}
