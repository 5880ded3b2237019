namespace GMac.Core.CodeGeneration;

/// <summary>
/// A node of the low-level expression trees that optimizer passes rewrite and emitters print.
/// Unlike the canonical symbolic <c>Scalar</c>, a tree keeps the shape chosen for evaluation
/// (factored, with temporaries), so substituting a temporary never expands a product.
/// Nodes are immutable and compare structurally; the hash is computed once.
/// </summary>
public abstract class Expr : IEquatable<Expr>
{
    private readonly int _hash;

    protected Expr(int hash) => _hash = hash;

    public abstract IReadOnlyList<Expr> Children { get; }

    /// <summary>The same node kind over new children.</summary>
    public abstract Expr WithChildren(IReadOnlyList<Expr> children);

    /// <summary>Number of nodes in the tree, a proxy for how much a shared subtree is worth.</summary>
    public int Size => _size ??= 1 + Children.Sum(c => c.Size);
    private int? _size;

    public bool IsLeaf => Children.Count == 0;

    public override int GetHashCode() => _hash;

    public override bool Equals(object? obj) => obj is Expr e && Equals(e);

    public bool Equals(Expr? other)
    {
        if (ReferenceEquals(this, other)) return true;
        if (other is null || other._hash != _hash || other.GetType() != GetType()) return false;
        return SameNode(other) && Children.SequenceEqual(other.Children);
    }

    /// <summary>Equality of the node itself, children aside.</summary>
    protected abstract bool SameNode(Expr other);

    /// <summary>A deterministic hash of a node kind and its children.</summary>
    protected static int CombineHashes(int seed, IEnumerable<Expr> children)
    {
        var h = seed;
        foreach (var c in children) h = StableHash.Combine(h, c._hash);
        return h;
    }

    /// <summary>Rebuilds the tree bottom-up through a rewrite applied to every node after its children.</summary>
    public Expr Rewrite(Func<Expr, Expr> rewrite)
    {
        if (IsLeaf) return rewrite(this);
        var children = Children;
        Expr[]? rebuilt = null;
        for (var i = 0; i < children.Count; i++)
        {
            var c = children[i].Rewrite(rewrite);
            if (rebuilt is null && !ReferenceEquals(c, children[i]))
            {
                rebuilt = new Expr[children.Count];
                for (var j = 0; j < i; j++) rebuilt[j] = children[j];
            }
            if (rebuilt is not null) rebuilt[i] = c;
        }
        return rewrite(rebuilt is null ? this : WithChildren(rebuilt));
    }

    /// <summary>Every node of the tree, parents before children.</summary>
    public IEnumerable<Expr> DescendantsAndSelf()
    {
        var stack = new Stack<Expr>();
        stack.Push(this);
        while (stack.Count > 0)
        {
            var e = stack.Pop();
            yield return e;
            foreach (var c in e.Children) stack.Push(c);
        }
    }

    public override string ToString() => ExprPrinter.Print(this, name => name);
}
