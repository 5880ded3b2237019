using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>One term coefficient × monomial of a <see cref="Scalar"/>; the coefficient is never zero.</summary>
public readonly record struct Term(Rational Coefficient, Monomial Monomial);
