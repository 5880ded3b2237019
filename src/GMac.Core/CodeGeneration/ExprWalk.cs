using System.Collections;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// The nodes of a tree, parents before children and the last child first. A <c>foreach</c> over it
/// allocates only its stack, which starts small and grows with the tree's width.
/// </summary>
public readonly struct ExprWalk(Expr root) : IEnumerable<Expr>
{
    public Enumerator GetEnumerator() => new(root);

    IEnumerator<Expr> IEnumerable<Expr>.GetEnumerator() => new Boxed(root);

    IEnumerator IEnumerable.GetEnumerator() => new Boxed(root);

    public struct Enumerator(Expr root)
    {
        private Expr[] _stack = [root, null!, null!, null!, null!, null!, null!, null!];
        private int _count = 1;

        public Expr Current { get; private set; } = null!;

        public bool MoveNext()
        {
            if (_count == 0) return false;
            var e = _stack[--_count];
            var children = e.Children;
            if (_count + children.Count > _stack.Length) Array.Resize(ref _stack, Math.Max(2 * _stack.Length, _count + children.Count));
            foreach (var c in children) _stack[_count++] = c;
            Current = e;
            return true;
        }
    }

    /// <summary>The same walk for LINQ and other interface callers.</summary>
    private sealed class Boxed(Expr root) : IEnumerator<Expr>
    {
        private Enumerator _walk = new(root);

        public Expr Current => _walk.Current;

        object IEnumerator.Current => Current;

        public bool MoveNext() => _walk.MoveNext();

        public void Reset() => throw new NotSupportedException();

        public void Dispose()
        {
        }
    }
}
