namespace GMac.Core.CodeGeneration.Cost;

/// <summary>
/// The estimated time of a code block in cycles per item when it runs over many independent
/// items. <see cref="CriticalPath"/> is the longest chain of dependent operations from the inputs
/// to an output (latencies added along it); <see cref="Throughput"/> the busiest unit (occupancy
/// over units, and issue). The core holds <see cref="ItemsInFlight"/> items at once (its window
/// over the operations one item takes), so their chains overlap: an item takes at least the
/// throughput and at least its chain shared among the items in flight.
/// </summary>
public sealed record TimeEstimate(double CriticalPath, double Throughput, double ItemsInFlight)
{
    public double Cycles => Math.Max(Throughput, CriticalPath / ItemsInFlight);

    public override string ToString() =>
        $"{Cycles:0.#} cycles (chain {CriticalPath:0.#} over {ItemsInFlight:0.#} items in flight, throughput {Throughput:0.#})";
}
