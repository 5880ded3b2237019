namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Moves a constant factor into a shared operand: in 2·(xy − wz) and 2·(xz + wy), each product
/// takes one factor already doubled, x2 = x + x, so the constant costs one addition per doubled
/// variable instead of one multiplication per use (the rotation matrix of a unit quaternion is
/// the classic case). Applies to products c·(Σ ±tₖ) whose every term is a product of two
/// factors, written there or held by a temporary that is read only inside such products with
/// the same c. Kept only when the block gets cheaper.
/// </summary>
public sealed class ConstantAbsorptionPass(Func<int, string> temporaryName) : IOptimizerPass
{
    private int _counter;

    public ConstantAbsorptionPass() : this(i => $"scl{i}") { }

    public string Name => "constant absorption";

    public CodeBlock Run(CodeBlock block)
    {
        foreach (var c in ScaledSums(block).Select(p => ((ConstantExpr)p.Children[0]).Value).Distinct().Order().ToArray())
        {
            var candidate = Absorb(block, c);
            if (candidate is not null && candidate.Statistics().Cost < block.Statistics().Cost) block = candidate;
        }
        return block;
    }

    /// <summary>Products of a constant (not ±1) and a sum or a single variable.</summary>
    private static IEnumerable<ProductExpr> ScaledSums(CodeBlock block) =>
        block.Statements.SelectMany(s => s.Expressions).SelectMany(e => e.DescendantsAndSelf()).OfType<ProductExpr>()
            .Where(p => p.Children.Count == 2 && p.Children[0] is ConstantExpr { Value: not (1 or -1) } && p.Children[1] is SumExpr or VariableExpr);

    private static IReadOnlyList<Expr> Terms(ProductExpr scaled) => scaled.Children[1] is SumExpr s ? s.Children : [scaled.Children[1]];

    private static Expr Body(Expr term) => term is NegateExpr n ? n.Operand : term;

    /// <summary>The two factors of a product of two non-constant factors.</summary>
    private static (Expr, Expr)? Pair(Expr e) => e is ProductExpr { Children.Count: 2 } p && p.Children.All(f => f is not ConstantExpr) ? (p.Children[0], p.Children[1]) : null;

    private CodeBlock? Absorb(CodeBlock block, double c)
    {
        var temps = block.Temporaries.ToDictionary(t => t.Target, t => t.Value, StringComparer.Ordinal);
        var uses = BlockRewriting.UseCounts(block.Statements);
        var sums = ScaledSums(block).Where(p => ((ConstantExpr)p.Children[0]).Value == c).Distinct().ToList();

        // A temporary can take the constant only if every read of it is a term of one of these sums.
        (Expr, Expr)? PairOf(Expr term) => Body(term) switch
        {
            VariableExpr v when temps.TryGetValue(v.Name, out var value) => Pair(value),
            var b => Pair(b),
        };
        while (true)
        {
            var reads = new Dictionary<string, int>(StringComparer.Ordinal);
            foreach (var p in sums)
                foreach (var t in Terms(p))
                    if (Body(t) is VariableExpr v) reads[v.Name] = reads.GetValueOrDefault(v.Name) + 1;
            var kept = sums.Where(p => Terms(p).All(t => PairOf(t) is not null
                && (Body(t) is not VariableExpr v || reads[v.Name] == uses.GetValueOrDefault(v.Name)))).ToList();
            if (kept.Count == sums.Count) break;
            sums = kept;
        }
        if (sums.Count == 0) return null;

        // Each product scales the factor that most products share, so few scaled copies are made.
        var products = sums.SelectMany(Terms).Select(t => PairOf(t)!.Value).Distinct().ToList();
        var frequency = products.SelectMany(p => new[] { p.Item1, p.Item2 }.Distinct()).GroupBy(f => f).ToDictionary(g => g.Key, g => g.Count());
        var scaledName = new Dictionary<Expr, string>();
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        Expr Scaled((Expr A, Expr B) pair)
        {
            var (keep, scale) = frequency[pair.B] > frequency[pair.A] || (frequency[pair.B] == frequency[pair.A] && pair.B.IsLeaf && !pair.A.IsLeaf) ? (pair.A, pair.B) : (pair.B, pair.A);
            if (!scaledName.TryGetValue(scale, out var name))
            {
                do name = temporaryName(_counter++); while (!taken.Add(name));
                scaledName[scale] = name;
            }
            return ExprFactory.Product(keep, ExprFactory.Variable(name));
        }

        var absorbedTemps = sums.SelectMany(Terms).Select(Body).OfType<VariableExpr>().Select(v => v.Name).ToHashSet(StringComparer.Ordinal);
        var sumSet = sums.Cast<Expr>().ToHashSet();
        var statements = new List<CodeStatement>();
        foreach (var s in block.Statements)
        {
            var rewritten = s is AssignmentStatement { IsOutput: false } a && absorbedTemps.Contains(a.Target)
                ? a with { Value = Scaled(Pair(a.Value)!.Value) }
                : BlockRewriting.MapExpressions(block.WithStatements([s]), e => BlockRewriting.ReplaceNodes(e, node =>
                    sumSet.Contains(node) ? ExprFactory.Sum(Terms((ProductExpr)node).Select(t =>
                    {
                        var body = Body(t) is VariableExpr ? Body(t) : Scaled(Pair(Body(t))!.Value);
                        return t is NegateExpr ? ExprFactory.Negate(body) : body;
                    })) : null)).Statements[0];
            statements.Add(rewritten);
        }
        // The scaled copies go first: they read only what the products read, and those are inputs or earlier temporaries.
        var copies = scaledName.Select(kv => (CodeStatement)new AssignmentStatement(kv.Value,
            c == 2 ? ExprFactory.Sum(kv.Key, kv.Key) : ExprFactory.Product(ExprFactory.Constant(c), kv.Key), false)).ToList();
        return Place(block, statements, copies);
    }

    /// <summary>Inserts each new statement right after the last statement defining a variable it reads.</summary>
    private static CodeBlock Place(CodeBlock block, List<CodeStatement> statements, List<CodeStatement> copies)
    {
        foreach (var copy in copies)
        {
            var reads = copy.Expressions.SelectMany(e => e.DescendantsAndSelf()).OfType<VariableExpr>().Select(v => v.Name).ToHashSet(StringComparer.Ordinal);
            var last = statements.FindLastIndex(s => s is AssignmentStatement a && reads.Contains(a.Target));
            statements.Insert(last + 1, copy);
        }
        return block.WithStatements(statements);
    }
}
