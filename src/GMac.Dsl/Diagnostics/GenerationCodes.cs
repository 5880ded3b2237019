namespace GMac.Dsl.Diagnostics;

/// <summary>Codes of problems found while generating a binding point (the 03xx range).</summary>
public static class GenerationCodes
{
    /// <summary>An AssumeMin above an AssumeMax (or a class-binding limit) of the same expression.</summary>
    public const string EmptyAssumption = "GMAC0312";

    /// <summary>A divisor that simplifies to zero once the bindings are known.</summary>
    public const string DivisionByZero = "GMAC0313";

    /// <summary>An operation whose symbolic evaluation would exceed the work limit.</summary>
    public const string TooLarge = "GMAC0314";
}
