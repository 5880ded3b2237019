using GMac.Core.Numerics;

namespace GMac.Dsl.Semantics;

/// <summary>
/// A blade that a multivector class fixes to an exact number (the no coefficient 1 of a normalized
/// conformal point). <see cref="Value"/> is the coefficient of the blade in frame order, so a
/// constant written on e2^e1 is stored negated on e1^e2.
/// </summary>
public sealed record ClassConstant(int Blade, Rational Value);
