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
    private readonly Expr[] _children;

    /// <summary><paramref name="children"/> becomes the node's own: callers pass a fresh array.</summary>
    protected Expr(int hash, Expr[] children)
    {
        _hash = hash;
        _children = children;
    }

    public ExprList Children => new(_children);

    /// <summary>The same node kind over new children.</summary>
    public abstract Expr WithChildren(IReadOnlyList<Expr> children);

    /// <summary>Number of nodes in the tree, a proxy for how much a shared subtree is worth.</summary>
    public int Size
    {
        get
        {
            if (_size == 0)
            {
                var size = 1;
                foreach (var c in _children) size += c.Size;
                _size = size;
            }
            return _size;
        }
    }

    private int _size;

    public bool IsLeaf => _children.Length == 0;

    public override int GetHashCode() => _hash;

    public override bool Equals(object? obj) => obj is Expr e && Equals(e);

    public bool Equals(Expr? other)
    {
        if (ReferenceEquals(this, other)) return true;
        if (other is null || other._hash != _hash || other.GetType() != GetType()) return false;
        return SameNode(other) && _children.AsSpan().SequenceEqual(other._children);
    }

    /// <summary>Equality of the node itself, children aside.</summary>
    protected abstract bool SameNode(Expr other);

    /// <summary>A deterministic hash of a node kind and its children.</summary>
    protected static int CombineHashes(int seed, Expr[] children)
    {
        var h = seed;
        foreach (var c in children) h = StableHash.Combine(h, c._hash);
        return h;
    }

    /// <summary>Rebuilds the tree bottom-up through a rewrite applied to every node after its children.</summary>
    public Expr Rewrite(Func<Expr, Expr> rewrite)
    {
        if (IsLeaf) return rewrite(this);
        var children = _children;
        Expr[]? rebuilt = null;
        for (var i = 0; i < children.Length; i++)
        {
            var c = children[i].Rewrite(rewrite);
            if (rebuilt is null && !ReferenceEquals(c, children[i]))
            {
                rebuilt = new Expr[children.Length];
                for (var j = 0; j < i; j++) rebuilt[j] = children[j];
            }
            if (rebuilt is not null) rebuilt[i] = c;
        }
        return rewrite(rebuilt is null ? this : WithChildren(rebuilt));
    }

    /// <summary>Every node of the tree, parents before children (the last child first).</summary>
    public ExprWalk DescendantsAndSelf() => new(this);

    public override string ToString() => ExprPrinter.Print(this, name => name);
}
