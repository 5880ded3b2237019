using System.Numerics;
using GMac.Core.Algebra;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Compilation;

/// <summary>
/// What code generation watches during an evaluation: every intermediate multivector (outside
/// <c>join on</c> regions) passes through <see cref="Name"/>, which may replace its coefficients
/// by named temporaries, and the top-level <c>output {…}</c> statements report their text with
/// the values of the coefficients they mention.
/// </summary>
public sealed class EvaluationObserver<T>
    where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
{
    public Func<Multivector<T>, Multivector<T>>? Name { get; init; }

    /// <summary>Name only what statements assign (and macro calls return), not every subexpression.</summary>
    public bool NameStatementsOnly { get; init; }

    public Action<BoundOutputStatement, IReadOnlyList<T>>? OutputText { get; init; }

    /// <summary>Values for the <c>&lt;member&gt;</c> references of class-binding expressions.</summary>
    public Func<string, T>? Member { get; init; }
}
