namespace GMac.Core.Symbolic;

/// <summary>A scalar expression text that cannot be read; carries the 1-based column of the problem.</summary>
public sealed class ScalarSyntaxException : FormatException
{
    public ScalarSyntaxException(string reason, int column, string text)
        : base($"column {column}: {reason}")
    {
        Reason = reason;
        Column = column;
        Text = text;
    }

    /// <summary>The problem without the position prefix.</summary>
    public string Reason { get; }

    /// <summary>1-based column in <see cref="Text"/>.</summary>
    public int Column { get; }

    /// <summary>0-based offset in <see cref="Text"/>.</summary>
    public int Position => Column - 1;

    public string Text { get; }
}
