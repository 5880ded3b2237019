using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>
/// Temporaries holding the sine and the cosine of one argument, which C# computes together with
/// <c>Math.SinCos</c> (one range reduction instead of two). Found once per block by the emitter: the
/// pair is declared at the first of its two statements and the second statement is dropped.
/// </summary>
internal sealed class SinCosPairs
{
    private readonly Dictionary<AssignmentStatement, (string Sine, string Cosine, Expr Argument)> _first = [];
    private readonly HashSet<AssignmentStatement> _dropped = [];

    public SinCosPairs(CodeBlock block)
    {
        // Temporaries assigned once only: a reassigned name cannot be declared by a tuple.
        var assignments = block.Statements.OfType<AssignmentStatement>().Where(a => !a.IsOutput)
            .GroupBy(a => a.Target, StringComparer.Ordinal)
            .Where(g => g.Count() == 1)
            .Select(g => g.Single())
            .ToList();
        var sines = new Dictionary<Expr, AssignmentStatement>();
        foreach (var a in assignments)
            if (a.Value is CallExpr { Function: "sin", Children: [var x] })
                sines.TryAdd(x, a);
        var order = block.Statements.Select((s, i) => (s, i)).ToDictionary(p => p.s, p => p.i);
        foreach (var a in assignments)
        {
            if (a.Value is not CallExpr { Function: "cos", Children: [var x] } || !sines.Remove(x, out var sine))
                continue;
            var (first, second) = order[sine] < order[a] ? (sine, a) : (a, sine);
            _first[first] = (sine.Target, a.Target, x);
            _dropped.Add(second);
        }
    }

    /// <summary>The pair a statement declares, when it is the first of one.</summary>
    public bool TryGetPair(AssignmentStatement statement, out (string Sine, string Cosine, Expr Argument) pair) =>
        _first.TryGetValue(statement, out pair);

    /// <summary>True for the second statement of a pair, already computed by the first.</summary>
    public bool IsDropped(CodeStatement statement) => statement is AssignmentStatement a && _dropped.Contains(a);
}
