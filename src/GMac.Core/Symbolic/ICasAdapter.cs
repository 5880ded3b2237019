namespace GMac.Core.Symbolic;

/// <summary>
/// The computer-algebra back end behind the fast canonical form: simplification that needs
/// assumptions or rules the canonical form does not apply by itself.
/// </summary>
public interface ICasAdapter
{
    /// <summary>Identifies the back end and its rule version; part of every cache key.</summary>
    string Name { get; }

    Scalar Simplify(Scalar expression, Assumptions assumptions);

    Scalar Parse(string text);
}
