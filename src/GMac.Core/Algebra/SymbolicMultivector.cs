using GMac.Core.Symbolic;

namespace GMac.Core.Algebra;

/// <summary>Operations that exist only for symbolic multivectors.</summary>
public static class SymbolicMultivector
{
    /// <summary>
    /// A multivector whose coefficient on each listed blade is a fresh variable named
    /// <see cref="VariableName"/>, e.g. "u.e1_e2" for blade e1^e2 of u.
    /// </summary>
    public static Multivector<Scalar> Variables(Frame frame, string prefix, IEnumerable<BasisBlade> blades) =>
        Multivector<Scalar>.FromTerms(frame, blades.Select(b => (b, Scalar.Variable(VariableName(frame, prefix, b)))));

    /// <summary>"prefix.e1_e2" for blade e1^e2, "prefix.scalar" for the scalar blade.</summary>
    public static string VariableName(Frame frame, string prefix, BasisBlade blade) =>
        blade.Id == 0 ? $"{prefix}.scalar" : $"{prefix}.{frame.BladeName(blade).Replace('^', '_')}";

    /// <summary>A general symbolic multivector: one variable per blade of the frame.</summary>
    public static Multivector<Scalar> Variables(Frame frame, string prefix) =>
        Variables(frame, prefix, Enumerable.Range(0, frame.BladeCount).Select(id => new BasisBlade(id)));

    /// <summary>A symbolic vector: one variable per basis vector.</summary>
    public static Multivector<Scalar> VectorVariables(Frame frame, string prefix) => Variables(frame, prefix, frame.BladesOfGrade(1));

    /// <summary>∂A/∂x, coefficient by coefficient.</summary>
    public static Multivector<Scalar> Derivative(this Multivector<Scalar> a, string variable) =>
        a.MapCoefficients(c => c.Derivative(variable));

    /// <summary>The numeric multivector for given variable values.</summary>
    public static Multivector<double> Evaluate(this Multivector<Scalar> a, IReadOnlyDictionary<string, double> values) =>
        a.Convert(c => c.Evaluate(values));

    public static Multivector<Scalar> Substitute(this Multivector<Scalar> a, IReadOnlyDictionary<string, Scalar> replacements) =>
        a.MapCoefficients(c => c.Substitute(replacements));

    /// <summary>Every variable that occurs in a coefficient.</summary>
    public static IReadOnlySet<string> VariableNames(this Multivector<Scalar> a)
    {
        var names = new HashSet<string>(StringComparer.Ordinal);
        foreach (var (_, c) in a.Terms) names.UnionWith(c.Variables);
        return names;
    }

    /// <summary>A symbolic copy of a numeric multivector (exact: every double is a rational).</summary>
    public static Multivector<Scalar> ToSymbolic(this Multivector<double> a) =>
        a.Convert(c => Scalar.Constant(Numerics.Rational.FromDouble(c)));
}
