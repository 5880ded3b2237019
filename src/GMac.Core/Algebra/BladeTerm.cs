using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>One term <c>Coefficient · e_Blade</c> of an exact product of basis blades.</summary>
public readonly record struct BladeTerm(int Blade, Rational Coefficient);
