namespace GMac.Core.CodeGeneration.Cost;

/// <summary>
/// Latency (cycles from operands to result) and reciprocal throughput (cycles an operation holds
/// its unit) of scalar double operations, with how many units of each kind a core has. The
/// defaults are AMD Zen 3/Zen 4 figures from published instruction tables (rounded): add and
/// multiply 3 cycles on two units each, fused multiply-add 4 on the two multiply units, division
/// 13 cycles holding the one divider 4.5, square root 20 holding it 9; a math library call (sin,
/// exp, atan2, …) is taken as 40 cycles of latency that also hold the core's issue for 20.
/// The core issues 6 operations a cycle and keeps 256 in flight (its reorder buffer), so a loop
/// over independent items overlaps the chains of several items.
/// </summary>
public sealed record OperationTimes
{
    public double AddLatency { get; init; } = 3;
    public double MultiplyLatency { get; init; } = 3;
    public double FusedMultiplyAddLatency { get; init; } = 4;
    public double DivideLatency { get; init; } = 13;
    public double SquareRootLatency { get; init; } = 20;
    public double CallLatency { get; init; } = 40;

    /// <summary>A negation is a sign-bit xor: one cycle, on any unit.</summary>
    public double NegateLatency { get; init; } = 1;

    /// <summary>Cycles one add holds one of the <see cref="AddUnits"/>.</summary>
    public double AddOccupancy { get; init; } = 1;
    public int AddUnits { get; init; } = 2;

    /// <summary>Cycles one multiply or fused multiply-add holds one of the <see cref="MultiplyUnits"/>.</summary>
    public double MultiplyOccupancy { get; init; } = 1;
    public int MultiplyUnits { get; init; } = 2;

    /// <summary>Cycles a division holds the divider (one unit, shared with square roots).</summary>
    public double DivideOccupancy { get; init; } = 4.5;
    public double SquareRootOccupancy { get; init; } = 9;

    /// <summary>Cycles a math library call keeps the core from other work.</summary>
    public double CallOccupancy { get; init; } = 20;

    /// <summary>Operations issued per cycle (loads of inputs and stores of outputs count).</summary>
    public double IssueWidth { get; init; } = 6;

    /// <summary>Operations in flight at once: how far past a waiting chain the core finds other work.</summary>
    public double ReorderWindow { get; init; } = 256;

    /// <summary>AMD Zen 3/Zen 4 (the defaults).</summary>
    public static OperationTimes Zen { get; } = new();
}
