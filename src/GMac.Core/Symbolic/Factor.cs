namespace GMac.Core.Symbolic;

/// <summary>One factor atom^power of a <see cref="Monomial"/>; the power is never zero.</summary>
public readonly record struct Factor(Atom Atom, int Power);
