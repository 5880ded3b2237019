using System.Collections;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// The children of an <see cref="Expr"/>: a read-only view of the node's own array. Passes walk
/// children millions of times per run, so <c>foreach</c> here uses a struct enumerator and asking
/// for the children allocates nothing.
/// </summary>
public readonly struct ExprList(Expr[] items) : IReadOnlyList<Expr>
{
    private readonly Expr[] _items = items;

    public int Count => _items.Length;

    public Expr this[int index] => _items[index];

    public Enumerator GetEnumerator() => new(_items);

    IEnumerator<Expr> IEnumerable<Expr>.GetEnumerator() => ((IEnumerable<Expr>)_items).GetEnumerator();

    IEnumerator IEnumerable.GetEnumerator() => _items.GetEnumerator();

    public Expr[] ToArray() => (Expr[])_items.Clone();

    public ReadOnlySpan<Expr> AsSpan() => _items;

    public struct Enumerator(Expr[] items)
    {
        private int _index = -1;

        public readonly Expr Current => items[_index];

        public bool MoveNext() => ++_index < items.Length;
    }
}
