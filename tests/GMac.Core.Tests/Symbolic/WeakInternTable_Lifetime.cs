using System.Runtime.CompilerServices;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class WeakInternTable_Lifetime
{
    [Fact]
    public void Equal_live_candidates_give_the_first_object()
    {
        var table = new WeakInternTable<string>(StringComparer.Ordinal);
        var first = table.GetOrAdd(new string('a', 3));
        var second = table.GetOrAdd(new string('a', 3));
        Assert.Same(first, second);
        Assert.NotSame(first, table.GetOrAdd(new string('b', 3)));
    }

    [Fact]
    public void Unreferenced_entries_are_swept()
    {
        var table = new WeakInternTable<string>(StringComparer.Ordinal);
        AddGarbage(table, 10_000);
        GC.Collect();
        GC.WaitForPendingFinalizers();
        GC.Collect();
        var kept = new List<string>();
        for (var i = 0; i < 10_000; i++) kept.Add(table.GetOrAdd($"kept{i}"));
        Assert.True(table.Count < 20_000, $"{table.Count} entries");
        // The survivors are still found.
        for (var i = 0; i < kept.Count; i++) Assert.Same(kept[i], table.GetOrAdd($"kept{i}"));
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void AddGarbage(WeakInternTable<string> table, int count)
    {
        for (var i = 0; i < count; i++) table.GetOrAdd($"garbage{i}");
    }
}
