using System.Text;
using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>
/// Prints a code block as C# over SIMD vectors (<c>Vector256&lt;double&gt;</c>, …), each lane one
/// independent evaluation of the scalar code: operators for + − × ÷ and negation, constants
/// broadcast once at the top, the vector forms of sqrt, sin, cos, sincos, exp, log and abs, and acos
/// on double lanes by <see cref="VectorArcCosine"/>. A function .NET has no vector form of (tan,
/// atan2, pow, and acos on float lanes) is computed lane by lane with the scalar <c>Math</c>
/// function, so every lane is what the scalar code gives for its inputs.
/// </summary>
public sealed class CSharpVectorEmitter : CSharpBlockEmitter
{
    public static CSharpVectorEmitter Instance { get; } = new();

    private CSharpVectorEmitter()
    {
    }

    /// <summary><c>Vector128&lt;double&gt;</c>, <c>Vector128&lt;float&gt;</c>, … <c>Vector&lt;float&gt;</c>.</summary>
    public override IReadOnlyList<string> ScalarTypes { get; } = VectorType.All.Select(v => v.Name).ToList();

    /// <summary>
    /// <c>var</c>: every value of vector code is of the vector type (operators on vectors, loads,
    /// broadcasts), and the type spelled out at each local is what C# style rules flag.
    /// </summary>
    protected override string DeclaredType(CSharpEmitOptions options) => "var";

    protected override ValueWriter CreateWriter(CSharpEmitOptions options, Func<string, string> variableText, Func<string, string> freshName) =>
        new Writer(VectorType.Find(options.ScalarType)!, variableText, freshName);

    private sealed class Writer(VectorType type, Func<string, string> variableText, Func<string, string> freshName) : ValueWriter
    {
        // Names given to lane results inside an expression, marked so they cannot be taken for the block's variables.
        private const string LaneMarker = "\u0001";

        private readonly Dictionary<string, string> _constants = new(StringComparer.Ordinal);
        private readonly List<string> _prelude = [];
        private readonly List<string> _before = [];

        public override string Print(Expr e) => ExprPrinter.Print(PerLane(e), Text, VectorFunction, Constant);

        public override string SinCos(Expr argument) => $"{type.Family}.SinCos({Print(argument)})";

        public override IReadOnlyList<string> TakeStatementsBefore()
        {
            var statements = _before.ToList();
            _before.Clear();
            return statements;
        }

        public override IReadOnlyList<string> Prelude() => _prelude;

        private string Text(string name) => name.StartsWith(LaneMarker, StringComparison.Ordinal) ? name[LaneMarker.Length..] : variableText(name);

        private string VectorFunction(string f) => f switch
        {
            "sin" => $"{type.Family}.Sin",
            "cos" => $"{type.Family}.Cos",
            "sqrt" => type.HasFixedWidth ? $"{type.Family}.Sqrt" : "Vector.SquareRoot",
            "exp" => $"{type.Family}.Exp",
            "log" => $"{type.Family}.Log",
            "abs" => $"{type.Family}.Abs",
            FusedMultiplyAdds.Function => $"{type.Family}.FusedMultiplyAdd",
            _ => throw new InvalidOperationException($"No vector function for '{f}'."),
        };

        private static bool HasVectorForm(Expr e) => e is not PowerExpr && (e is not CallExpr call || call.Function is "sin" or "cos" or "sqrt" or "exp" or "log" or "abs" or FusedMultiplyAdds.Function);

        /// <summary>A constant as a vector: broadcast once, at the top, into a local named after nothing else.</summary>
        private string Constant(ConstantExpr c)
        {
            var literal = ScalarLiteral(c, type.IsSingle);
            if (_constants.TryGetValue(literal, out var name)) return name;
            name = _constants[literal] = freshName("C");
            _prelude.Add($"var {name} = {type.Family}.Create({literal});");
            return name;
        }

        /// <summary>
        /// The expression with every call that has no vector form replaced by a local holding its
        /// lanes, computed before the statement: innermost first, arguments that are not plain
        /// names evaluated once into locals of their own.
        /// </summary>
        private Expr PerLane(Expr e)
        {
            if (e.Children.Count == 0) return e;
            var children = e.Children.Select(PerLane).ToList();
            var node = children.SequenceEqual(e.Children) ? e : e.WithChildren(children);
            if (HasVectorForm(node)) return node;
            if (node is CallExpr { Function: "acos" } && type.HasFixedWidth && !type.IsSingle)
                return new VariableExpr(LaneMarker + VectorArcCosine.Emit(type.Family, Named(node.Children[0]),
                    v => Constant(new ConstantExpr(v)), () => freshName("L"), _before));
            var single = type.IsSingle;
            // Constant arguments stay scalar literals; the rest are read lane by lane. Extension methods are
            // called as static methods, which compile where the file lacks the vector types' using (VectorTypeNames).
            var arguments = node.Children.Select(a => a is ConstantExpr c ? (Literal: ScalarLiteral(c, single), Vector: (string?)null) : (Literal: (string?)null, Vector: Named(a))).ToList();
            var function = ScalarFunction(node is PowerExpr ? "pow" : ((CallExpr)node).Function, single);
            var exponent = node is PowerExpr p ? ", " + ScalarLiteral(new ConstantExpr(p.Exponent), single) : "";
            string Lane(string index) =>
                $"{function}({string.Join(", ", arguments.Select(a => a.Literal ?? (type.HasFixedWidth ? $"{type.Family}.GetElement({a.Vector}, {index})" : $"{a.Vector}[{index}]")))}{exponent})";
            var result = freshName("L");
            if (type.HasFixedWidth)
            {
                _before.Add($"var {result} = {type.Family}.Create({string.Join(", ", Enumerable.Range(0, type.Lanes).Select(i => Lane(i.ToString(System.Globalization.CultureInfo.InvariantCulture))))});");
            }
            else
            {
                // Vector<T> has as many lanes as the machine gives it: a loop over them.
                var i = freshName("I");
                _before.Add($"var {result} = {type.Name}.Zero;");
                _before.Add($"for (var {i} = 0; {i} < {type.Name}.Count; {i}++) {result} = {type.Family}.WithElement({result}, {i}, {Lane(i)});");
            }
            return new VariableExpr(LaneMarker + result);
        }

        /// <summary>The value as a name of a vector: a variable's own text when that is simple, else a local computed once.</summary>
        private string Named(Expr a)
        {
            var text = Print(a);
            if (a is VariableExpr && IsSimple(text)) return text;
            var name = freshName("L");
            _before.Add(new StringBuilder().Append("var ").Append(name).Append(" = ").Append(text).Append(';').ToString());
            return name;
        }
    }
}
