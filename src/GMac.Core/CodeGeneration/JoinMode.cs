namespace GMac.Core.CodeGeneration;

/// <summary>How intermediate results become code (thesis §4.8.7).</summary>
public enum JoinMode
{
    /// <summary>Generate both forms below and keep the one with fewer operations.</summary>
    Automatic,
    /// <summary>Outputs as direct functions of the inputs, fully expanded then factored ("join on").</summary>
    Joined,
    /// <summary>Intermediate multivector coefficients kept as temporaries ("join off").</summary>
    Split,
}
