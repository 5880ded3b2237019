namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Where a region's statements land: <see cref="Id"/> tells regions of the same member (method,
/// property, constructor…) apart from others, whose locals cannot clash with them; <see cref="Names"/>
/// are the identifiers of that member outside region bodies and the members of its enclosing types.
/// </summary>
internal sealed record RegionScope(int Id, IReadOnlySet<string> Names)
{
    /// <summary>Which names may refer to storage elsewhere (ref parameters and locals, pointers, spans), which are plain locals.</summary>
    public StorageNames Storage { get; init; } = StorageNames.None;
}
