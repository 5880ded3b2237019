namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Where a region's statements land, in a parse of its file with every region body replaced by one
/// statement: the function holding them (<see cref="Function"/>, the same number for regions of one
/// method, lambda or local function), the block whose locals they join, and the locals and
/// parameters already declared there (name → what and where), which the region's code must not declare again.
/// </summary>
internal sealed record RegionPlacement(int Function, int BlockStart, int BlockEnd, IReadOnlyDictionary<string, string> Declared)
{
    /// <summary>For a region whose place is not known: it clashes with nothing.</summary>
    public static RegionPlacement Unknown { get; } = new(-2, 0, 0, new Dictionary<string, string>());

    /// <summary>
    /// Whether locals declared by the two regions' code would clash: same function, and one block
    /// inside (or the same as) the other. Lambdas and local functions may reuse outer names (C# 8).
    /// </summary>
    public bool SharesLocalsWith(RegionPlacement other) =>
        Function == other.Function && Function != Unknown.Function
        && ((BlockStart <= other.BlockStart && other.BlockEnd <= BlockEnd) || (other.BlockStart <= BlockStart && BlockEnd <= other.BlockEnd));
}
