namespace GMac.Core.CodeGeneration;

/// <summary>
/// Straight-line code: single assignments of temporaries and outputs over named inputs. Inputs
/// are read through <see cref="InputText"/> (the target-language text bound to each input
/// variable); outputs are written to <see cref="OutputTargets"/>. Passes return new blocks.
/// </summary>
public sealed class CodeBlock
{
    public IReadOnlyList<CodeStatement> Statements { get; }

    /// <summary>Input variable name → the expression text that supplies it.</summary>
    public IReadOnlyDictionary<string, string> InputText { get; }

    /// <summary>Output name → the assignable text that receives it.</summary>
    public IReadOnlyDictionary<string, string> OutputTargets { get; }

    public CodeBlock(IEnumerable<CodeStatement> statements, IReadOnlyDictionary<string, string> inputText, IReadOnlyDictionary<string, string> outputTargets)
    {
        Statements = statements.ToArray();
        InputText = inputText;
        OutputTargets = outputTargets;
    }

    /// <summary>
    /// Target-language expressions evaluated once, in order, before the statements (calls and other
    /// expressions with effects): input texts refer to the <c>i</c>-th by <see cref="EvaluatedOnceMarker"/>.
    /// </summary>
    public IReadOnlyList<string> EvaluatedOnce { get; init; } = [];

    /// <summary>The placeholder for the value of <see cref="EvaluatedOnce"/>[<paramref name="index"/>] in input texts; no C# text contains it.</summary>
    public static string EvaluatedOnceMarker(int index) => $"\u0001{index}\u0001";

    /// <summary>The inputs that are coordinates of points or vectors, for rewrites over their differences.</summary>
    public IReadOnlyList<InputPoint> Points { get; init; } = [];

    public CodeBlock WithStatements(IEnumerable<CodeStatement> statements) => new(statements, InputText, OutputTargets) { EvaluatedOnce = EvaluatedOnce, Points = Points };

    private int? _structureHash;

    /// <summary>A hash of the statements, equal for blocks with <see cref="HasSameStatements"/>; computed once.</summary>
    internal int StructureHash => _structureHash ??= HashStatements();

    private int HashStatements()
    {
        var h = Statements.Count;
        foreach (var s in Statements)
        {
            h = s switch
            {
                AssignmentStatement a => StableHash.Combine(StableHash.Combine(h, StableHash.Of(a.Target)), a.Value.GetHashCode() ^ (a.IsOutput ? 1 : 0)),
                VerbatimStatement v => v.Parts.Aggregate(h, (acc, p) => StableHash.Combine(acc, p.Value?.GetHashCode() ?? StableHash.Of(p.Text ?? ""))),
                _ => StableHash.Combine(h, 17),
            };
        }
        return h;
    }

    public IEnumerable<AssignmentStatement> Temporaries => Statements.OfType<AssignmentStatement>().Where(a => !a.IsOutput);

    public IEnumerable<AssignmentStatement> Outputs => Statements.OfType<AssignmentStatement>().Where(a => a.IsOutput);

    public bool IsTemporary(string name) => Temporaries.Any(t => t.Target == name);

    public CodeStatistics Statistics() => CodeStatistics.Of(this);

    /// <summary>
    /// Whether both blocks run the same statements (expressions compared structurally, verbatim text
    /// part by part). The structure hashes, computed once per block, settle most unequal pairs.
    /// </summary>
    public bool HasSameStatements(CodeBlock other) =>
        ReferenceEquals(this, other) ||
        Statements.Count == other.Statements.Count && StructureHash == other.StructureHash && Statements.Zip(other.Statements).All(p => p switch
        {
            (VerbatimStatement a, VerbatimStatement b) => a.Parts.SequenceEqual(b.Parts),
            var (a, b) => a.Equals(b),
        });

    /// <summary>Evaluates the block for given input values (for tests and verification).</summary>
    public IReadOnlyDictionary<string, double> Evaluate(IReadOnlyDictionary<string, double> inputs)
    {
        var values = new Dictionary<string, double>(inputs, StringComparer.Ordinal);
        var outputs = new Dictionary<string, double>(StringComparer.Ordinal);
        foreach (var s in Statements.OfType<AssignmentStatement>())
        {
            var v = ExprEvaluator.Evaluate(s.Value, values);
            values[s.Target] = v;
            if (s.IsOutput) outputs[s.Target] = v;
        }
        return outputs;
    }

    public override string ToString() =>
        string.Join(Environment.NewLine, Statements.Select(s => s switch
        {
            AssignmentStatement a => $"{(a.IsOutput ? "" : "temp ")}{a.Target} = {a.Value};",
            VerbatimStatement v => string.Concat(v.Parts.Select(p => p.Text ?? $"<{p.Value}>")),
            _ => s.ToString(),
        }));
}
