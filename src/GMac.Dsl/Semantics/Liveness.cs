namespace GMac.Dsl.Semantics;

/// <summary>
/// Which statements of a macro can reach its outputs or its output text. The others (temporaries
/// never read, or read only by such) are skipped when the macro is evaluated, so they cost nothing
/// however many or large they are. One backward pass, linear in the size of the statements.
/// </summary>
internal static class Liveness
{
    public static bool[] Of(IReadOnlyList<BoundStatement> statements, IEnumerable<VariableSymbol> outputs)
    {
        var live = new bool[statements.Count];
        var needed = new HashSet<VariableSymbol>(outputs);
        for (var i = statements.Count - 1; i >= 0; i--)
        {
            switch (statements[i])
            {
                case BoundAssignment a:
                    if (!needed.Remove(a.Target)) continue; // its value is overwritten or never read
                    live[i] = true;
                    if (!AddReads(a.Value, needed)) return AllLive(live);
                    break;
                case BoundCallStatement c:
                    // Kept whatever it assigns: a call is one statement, its outputs are not split.
                    live[i] = true;
                    foreach (var b in c.Bindings.Where(b => b.Target is not null)) needed.Remove(b.Target!);
                    if (!c.Bindings.Where(b => b.Value is not null).All(b => AddReads(b.Value!, needed))) return AllLive(live);
                    break;
                case BoundOutputStatement o:
                    live[i] = true;
                    if (!o.References.All(r => AddReads(r, needed))) return AllLive(live);
                    break;
                default:
                    live[i] = true;
                    break;
            }
        }
        return live;
    }

    private static bool[] AllLive(bool[] live)
    {
        Array.Fill(live, true);
        return live;
    }

    /// <summary>Adds the variables the expression reads, walked without recursion; false for a node
    /// kind it does not know, whose reads are then unknown.</summary>
    private static bool AddReads(BoundExpression root, HashSet<VariableSymbol> needed)
    {
        var pending = new Stack<BoundExpression>();
        pending.Push(root);
        while (pending.Count > 0)
        {
            switch (pending.Pop())
            {
                case BoundVariableReference v:
                    needed.Add(v.Variable);
                    break;
                case BoundBinaryOperation b:
                    pending.Push(b.Left);
                    pending.Push(b.Right);
                    break;
                case BoundUnaryOperation u:
                    pending.Push(u.Operand);
                    break;
                case BoundCoefficient c:
                    pending.Push(c.Operand);
                    break;
                case BoundCast c:
                    pending.Push(c.Operand);
                    break;
                case BoundGradeProjection g:
                    pending.Push(g.Operand);
                    break;
                case BoundTransformApplication t:
                    pending.Push(t.Operand);
                    break;
                case BoundVersorApplication v:
                    pending.Push(v.Versor);
                    pending.Push(v.Operand);
                    break;
                case BoundDifferentiation d:
                    pending.Push(d.Operand);
                    pending.Push(d.Variable);
                    break;
                case BoundMacroCall m:
                    foreach (var a in m.Arguments) pending.Push(a);
                    break;
                case BoundScalarFunctionCall f:
                    foreach (var a in f.Arguments) pending.Push(a);
                    break;
                case BoundMultivectorConstruction m:
                    foreach (var c in m.Coefficients) pending.Push(c.Value);
                    break;
                case BoundNumber or BoundConstantReference or BoundMemberReference:
                    break;
                default:
                    return false;
            }
        }
        return true;
    }
}
