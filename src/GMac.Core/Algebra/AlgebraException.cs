namespace GMac.Core.Algebra;

/// <summary>
/// A geometric-algebra operation was asked something it cannot answer (a null versor to invert,
/// operands from different frames, a malformed metric). The message names the frame and the value,
/// so the DSL can turn it into a diagnostic.
/// </summary>
public sealed class AlgebraException : Exception
{
    public string? FrameName { get; }

    /// <summary>True when the operation was refused for its size rather than for its meaning.</summary>
    public bool ExceedsLimit { get; init; }

    /// <summary>True when a multivector to invert has no inverse (a null versor, A adj(A) = 0).</summary>
    public bool NotInvertible { get; init; }

    public AlgebraException(string? frameName, string message)
        : base(frameName is null ? message : $"Frame '{frameName}': {message}")
    {
        FrameName = frameName;
    }
}
