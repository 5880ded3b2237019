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
        const int garbage = 10_000;
        var table = new WeakInternTable<string>(StringComparer.Ordinal);
        AddGarbage(table, garbage);
        GC.Collect();
        GC.WaitForPendingFinalizers();
        GC.Collect();
        // The table sweeps when it reaches twice its live size at the last sweep, so at most
        // 2 × garbage entries; adding that many live ones must pass a sweep, which drops every
        // dead entry. From then on only live entries are added: the count is exactly theirs.
        var kept = new List<string>();
        for (var i = 0; i < 2 * garbage; i++) kept.Add(table.GetOrAdd($"kept{i}"));
        Assert.Equal(kept.Count, table.Count);
        // The survivors are still found.
        for (var i = 0; i < kept.Count; i++) Assert.Same(kept[i], table.GetOrAdd($"kept{i}"));
        Assert.Equal(kept.Count, table.Count);
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void AddGarbage(WeakInternTable<string> table, int count)
    {
        for (var i = 0; i < count; i++) table.GetOrAdd($"garbage{i}");
    }
}
