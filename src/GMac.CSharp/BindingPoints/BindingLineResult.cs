using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// A <c>//GMac.</c> line read at a 1-based <see cref="Line"/> and <see cref="Column"/> (where the
/// <c>//</c> starts): either its <see cref="Spec"/> or the <see cref="Error"/> that rejects it.
/// </summary>
public sealed record BindingLineResult(int Line, int Column, BindingSpec? Spec, string? Error)
{
    public bool Succeeded => Spec is not null;
}
