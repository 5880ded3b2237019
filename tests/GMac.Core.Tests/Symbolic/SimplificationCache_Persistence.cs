using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public sealed class SimplificationCache_Persistence : IDisposable
{
    private readonly string _directory = Path.Combine(Path.GetTempPath(), "gmac-cache-test-" + Guid.NewGuid().ToString("N"));
    private static readonly Scalar X = Scalar.Variable("x");
    private static readonly Scalar Root = Scalar.Sqrt(X * X);
    private static readonly Assumptions NonNegative = Assumptions.None.WithMinimum("x", 0);

    public void Dispose()
    {
        if (Directory.Exists(_directory)) Directory.Delete(_directory, recursive: true);
    }

    [Fact]
    public void Repeated_questions_are_answered_from_memory()
    {
        var cas = new CachingCasAdapter(new RuleBasedCas(), new SimplificationCache());
        Assert.Same(X, cas.Simplify(Root, NonNegative));
        Assert.Same(X, cas.Simplify(Root, NonNegative));
        Assert.Same(Scalar.Abs(X), cas.Simplify(Root, Assumptions.None));
        Assert.Equal(1, cas.TotalHits); // the repeat is answered by identity, without a text key
        Assert.Equal(1, cas.IdentityHits);
        Assert.Equal(2, cas.Cache.Misses);
        Assert.Null(cas.Cache.FilePath);
    }

    [Fact]
    public void A_second_cache_over_the_same_directory_answers_from_disk()
    {
        var first = new CachingCasAdapter(new RuleBasedCas(), new SimplificationCache(_directory));
        Assert.Same(X, first.Simplify(Root, NonNegative));
        first.Cache.Flush();
        Assert.True(File.Exists(first.Cache.FilePath));

        var second = new CachingCasAdapter(new CountingCas(), new SimplificationCache(_directory));
        Assert.Same(X, second.Simplify(Root, NonNegative));
        Assert.Equal(1, second.Cache.DiskHits);
        Assert.Equal(0, second.Cache.Misses);
        Assert.Equal(0, ((CountingCas)second.Inner).Calls);
    }

    [Fact]
    public void Deleting_the_file_is_harmless()
    {
        var cache = new SimplificationCache(_directory);
        var cas = new CachingCasAdapter(new RuleBasedCas(), cache);
        cas.Simplify(Root, NonNegative);
        cache.Flush();
        File.Delete(cache.FilePath!);
        Assert.Same(Scalar.Abs(X), cas.Simplify(Root, Assumptions.None));
        cache.Flush();
        Assert.True(File.Exists(cache.FilePath));

        Directory.Delete(_directory, recursive: true);
        var fresh = new CachingCasAdapter(new RuleBasedCas(), new SimplificationCache(_directory));
        Assert.Same(X, fresh.Simplify(Root, NonNegative));
        Assert.Equal(1, fresh.Cache.Misses);
    }

    [Fact]
    public void Corrupted_and_truncated_lines_are_ignored()
    {
        var cache = new SimplificationCache(_directory);
        cache.Add("k1", X + Scalar.One);
        cache.Add("k2", Scalar.Sin(X));
        cache.Add("k3", Scalar.Pow(X, 3));
        cache.Flush();
        var lines = File.ReadAllLines(cache.FilePath!);
        Assert.Equal(3, lines.Length);
        // k1's answer is altered, k3's line is cut short, and garbage is appended.
        Assert.Contains("\t1 + x\t", lines[0]);
        lines[0] = lines[0].Replace("\t1 + x\t", "\t2 + x\t");
        File.WriteAllText(cache.FilePath!, string.Join('\n', lines[0], lines[1], lines[2][..^5]) + "\n\u0000\u00ff garbage\twith\ttabs");

        var reader = new SimplificationCache(_directory);
        Assert.False(reader.TryGet("k1", out _));
        Assert.True(reader.TryGet("k2", out var k2));
        Assert.Same(Scalar.Sin(X), k2);
        Assert.False(reader.TryGet("k3", out _));

        // Appending after the torn line still gives a readable entry.
        reader.Add("k4", Scalar.Cos(X));
        reader.Flush();
        Assert.True(new SimplificationCache(_directory).TryGet("k4", out var k4));
        Assert.Same(Scalar.Cos(X), k4);
    }

    [Fact]
    public void Answers_reach_the_file_in_one_append_when_flushed()
    {
        var cache = new SimplificationCache(_directory);
        cache.Add("a", X);
        cache.Add("b", Scalar.Sin(X));
        Assert.False(File.Exists(cache.FilePath)); // nothing written per answer
        cache.Flush();
        Assert.Equal(2, File.ReadAllLines(cache.FilePath!).Length);
        cache.Flush(); // nothing pending: nothing appended
        Assert.Equal(2, File.ReadAllLines(cache.FilePath!).Length);
    }

    [Fact]
    public void Keys_depend_on_assumptions_and_adapter()
    {
        var cas = new CachingCasAdapter(new RuleBasedCas(), new SimplificationCache());
        Assert.NotEqual(cas.KeyOf(Root, NonNegative), cas.KeyOf(Root, Assumptions.None));
        Assert.Equal(cas.KeyOf(Root, Assumptions.None.WithMinimum("x", 0)), cas.KeyOf(Root, NonNegative));
        Assert.Contains(new RuleBasedCas().Name, cas.KeyOf(Root, NonNegative));
    }

    [Fact]
    public void Keys_stay_short_for_large_expressions_and_tell_expressions_apart()
    {
        var cas = new CachingCasAdapter(new RuleBasedCas(), new SimplificationCache());
        var large = SharedDenominatorExpression(60);
        Assert.True(large.ToString().Length > 20_000);
        Assert.True(cas.KeyOf(large, Assumptions.None).Length < 200);

        var trees = new RandomExpressionTrees(seed: 17);
        var keys = new Dictionary<string, Scalar>(StringComparer.Ordinal);
        for (var i = 0; i < 2000; i++)
        {
            var s = trees.Next(depth: 4).Symbolic;
            var key = cas.KeyOf(s, Assumptions.None);
            if (keys.TryGetValue(key, out var earlier)) Assert.Same(earlier, s);
            else keys[key] = s;
        }
        Assert.True(keys.Count > 500);
    }

    [Fact]
    public void A_large_answer_with_a_shared_denominator_is_stored_once_per_distinct_part_and_read_back()
    {
        var expression = SharedDenominatorExpression(60);
        var first = new CachingCasAdapter(new CountingCas(), new SimplificationCache(_directory));
        Assert.Same(expression, first.Simplify(expression, Assumptions.None));
        first.Cache.Flush();
        // Printed plainly, the 60-term denominator would be repeated in each of the 60 terms.
        Assert.True(new FileInfo(first.Cache.FilePath!).Length * 10 < expression.ToString().Length);

        var second = new CachingCasAdapter(new CountingCas(), new SimplificationCache(_directory));
        Assert.Same(expression, second.Simplify(expression, Assumptions.None));
        Assert.Equal(1, second.Cache.DiskHits);
        Assert.Equal(0, ((CountingCas)second.Inner).Calls);
    }

    /// <summary>Σ xᵢ·sin(xᵢ) / Σ xⱼ²: each term carries the same inverse of a long sum.</summary>
    private static Scalar SharedDenominatorExpression(int n)
    {
        var xs = Enumerable.Range(0, n).Select(i => Scalar.Variable($"x{i}")).ToArray();
        var denominator = xs.Aggregate(Scalar.Zero, (sum, x) => sum + x * x);
        return xs.Aggregate(Scalar.Zero, (sum, x) => sum + x * Scalar.Sin(x)) / denominator;
    }

    private sealed class CountingCas : ICasAdapter
    {
        public int Calls { get; private set; }
        public string Name => new RuleBasedCas().Name;
        public Scalar Parse(string text) => Scalar.Parse(text);

        public Scalar Simplify(Scalar expression, Assumptions assumptions)
        {
            Calls++;
            return expression;
        }
    }
}
