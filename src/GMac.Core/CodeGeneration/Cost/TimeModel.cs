namespace GMac.Core.CodeGeneration.Cost;

/// <summary>
/// Estimates what a code block costs in time rather than in operations: a division on the path
/// to every output costs more than a few extra additions beside it. Sums and products are
/// evaluated left to right, as C# does, so a + b + c is two dependent additions.
/// </summary>
public static class TimeModel
{
    /// <summary>The estimate with the default (Zen) figures and no fused multiply-add.</summary>
    public static TimeEstimate Estimate(CodeBlock block) => Estimate(block, OperationTimes.Zen, fusedMultiplyAdd: false);

    /// <param name="fusedMultiplyAdd">Whether a product added to a sum is one fused operation (the emitter contracts them).</param>
    public static TimeEstimate Estimate(CodeBlock block, OperationTimes times, bool fusedMultiplyAdd)
    {
        ArgumentNullException.ThrowIfNull(block);
        ArgumentNullException.ThrowIfNull(times);
        var walk = new Walk(times, fusedMultiplyAdd);
        var path = 0.0;
        foreach (var statement in block.Statements)
        {
            foreach (var e in statement.Expressions)
            {
                var ready = walk.Ready(e);
                if (statement is AssignmentStatement { IsOutput: false } a) walk.Named[a.Target] = ready;
                else path = Math.Max(path, ready);
            }
        }
        // every input is loaded and every output stored once per item
        var operations = walk.Operations + block.InputText.Count + block.OutputTargets.Count;
        var throughput = Math.Max(walk.Throughput(), operations / times.IssueWidth);
        return new TimeEstimate(path, throughput, Math.Max(1, times.ReorderWindow / Math.Max(1, operations)));
    }

    private sealed class Walk(OperationTimes t, bool fma)
    {
        public readonly Dictionary<string, double> Named = new(StringComparer.Ordinal);
        private double _adds, _muls, _divider, _calls;
        private int _others;
        private readonly HashSet<Expr> _trigonometric = [];

        public int Operations => (int)_adds + (int)_muls + _others;

        public double Throughput() => Math.Max(
            Math.Max(_adds * t.AddOccupancy / t.AddUnits, _muls * t.MultiplyOccupancy / t.MultiplyUnits),
            Math.Max(_divider, _calls));

        /// <summary>When the value of <paramref name="e"/> is ready, counting its operations as it goes.</summary>
        public double Ready(Expr e)
        {
            switch (e)
            {
                case VariableExpr v:
                    return Named.GetValueOrDefault(v.Name); // inputs are ready at the start
                case ConstantExpr:
                    return 0;
                case NegateExpr n:
                    _others++;
                    return Ready(n.Operand) + t.NegateLatency;
                case SumExpr s:
                {
                    var ready = Ready(s.Children[0]);
                    for (var i = 1; i < s.Children.Count; i++)
                    {
                        var child = s.Children[i];
                        var operand = child is NegateExpr neg ? neg.Operand : child;
                        if (fma && operand is ProductExpr p)
                        {
                            // the last factor's product fused with the add: one operation on a multiply unit
                            var (left, right) = ProductOperands(p);
                            _muls++;
                            ready = Math.Max(ready, Math.Max(left, right)) + t.FusedMultiplyAddLatency;
                            continue;
                        }
                        _adds++;
                        ready = Math.Max(ready, Ready(operand)) + t.AddLatency;
                    }
                    return ready;
                }
                case ProductExpr p:
                {
                    var (left, right) = ProductOperands(p);
                    _muls++;
                    return Math.Max(left, right) + t.MultiplyLatency;
                }
                case QuotientExpr q:
                    _others++;
                    _divider += t.DivideOccupancy;
                    return Math.Max(Ready(q.Numerator), Ready(q.Denominator)) + t.DivideLatency;
                case PowerExpr pw:
                {
                    var ready = Ready(pw.Base);
                    for (var k = 1; k < Math.Abs(pw.Exponent); k++)
                    {
                        _muls++;
                        ready += t.MultiplyLatency;
                    }
                    if (pw.Exponent < 0)
                    {
                        _others++;
                        _divider += t.DivideOccupancy;
                        ready += t.DivideLatency;
                    }
                    return ready;
                }
                case CallExpr c:
                {
                    var ready = c.Children.Select(Ready).DefaultIfEmpty(0).Max();
                    // the sine and the cosine of one argument are one call (the emitter pairs them)
                    if (c is { Function: "sin" or "cos", Children: [var x] } && !_trigonometric.Add(x)) return ready + t.CallLatency;
                    _others++;
                    if (c.Function == "sqrt")
                    {
                        _divider += t.SquareRootOccupancy;
                        return ready + t.SquareRootLatency;
                    }
                    if (c.Function == "abs") return ready + t.NegateLatency;
                    _calls += t.CallOccupancy;
                    return ready + t.CallLatency;
                }
                default:
                    return e.Children.Select(Ready).DefaultIfEmpty(0).Max();
            }
        }


        /// <summary>
        /// The readiness of the two operands of a product's last multiplication (all but the last
        /// factor, left to right, then the last), counting the multiplications before it.
        /// </summary>
        private (double Left, double Right) ProductOperands(ProductExpr p)
        {
            var ready = Ready(p.Children[0]);
            for (var i = 1; i < p.Children.Count - 1; i++)
            {
                _muls++;
                ready = Math.Max(ready, Ready(p.Children[i])) + t.MultiplyLatency;
            }
            return (ready, Ready(p.Children[^1]));
        }
    }
}
