using System.Collections.Concurrent;
using System.Collections;
using System.Reflection;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Generation;

/// <summary>Searches bound statements and expressions for a node kind, through their record properties.</summary>
internal static class BoundTree
{
    public static bool Contains<TNode>(object node) => Contains(node, typeof(TNode), 0);

    private static bool Contains(object? node, Type kind, int depth)
    {
        if (node is null || depth > 256) return false;
        if (kind.IsInstanceOfType(node)) return true;
        if (node is not (BoundStatement or BoundExpression or CoefficientValue)) return false;
        foreach (var property in Properties.GetOrAdd(node.GetType(), ReadableProperties))
        {
            var value = property.GetValue(node);
            if (value is BoundStatement or BoundExpression or CoefficientValue)
            {
                if (Contains(value, kind, depth + 1)) return true;
            }
            else if (value is IEnumerable items and not string)
            {
                foreach (var item in items)
                    if (Contains(item, kind, depth + 1)) return true;
            }
        }
        return false;
    }

    // Reflection over a node's type is the same for every node of that type: asked once.
    private static readonly ConcurrentDictionary<Type, PropertyInfo[]> Properties = new();

    private static PropertyInfo[] ReadableProperties(Type type) =>
        type.GetProperties(BindingFlags.Public | BindingFlags.Instance).Where(p => p.GetIndexParameters().Length == 0).ToArray();
}
