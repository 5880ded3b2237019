using System.Text;
using GMac.Core.CodeGeneration;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// A block's statements over its bound names (the inputs' texts, the outputs' targets), one
/// <c>target = value;</c> a line in the infix syntax of <see cref="ExprPrinter"/>: what a test reads of
/// the code without any host language's declarations or library calls.
/// </summary>
internal static class BlockText
{
    public static string Of(CodeBlock block)
    {
        var text = new StringBuilder();
        foreach (var s in block.Statements.OfType<AssignmentStatement>())
        {
            var target = s.IsOutput && block.OutputTargets.TryGetValue(s.Target, out var t) ? t : s.Target;
            var value = ExprPrinter.Print(s.Value, name => block.InputText.TryGetValue(name, out var input) ? input : name);
            text.Append(target).Append(" = ").Append(value).Append(";\n");
        }
        return text.ToString();
    }
}
