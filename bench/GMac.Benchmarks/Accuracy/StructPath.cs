using System.Reflection;

namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// Reads and writes the double reached by a C# member path such as <c>q.P1.x</c> inside a boxed
/// struct, the first identifier naming the struct itself: the texts that binding points bind.
/// </summary>
public static class StructPath
{
    public static bool IsPath(string text) =>
        text.Split('.').All(p => p.Length > 0 && (char.IsLetter(p[0]) || p[0] == '_') && p.All(c => char.IsLetterOrDigit(c) || c == '_'));

    public static double Read(object root, string path)
    {
        var value = root;
        foreach (var member in Members(path)) value = Field(value.GetType(), member).GetValue(value)!;
        return value is double d ? d : throw new InvalidOperationException($"'{path}' is not a double");
    }

    /// <summary>Writes into a boxed struct, rebuilding each nested struct on the way back up; returns the new box.</summary>
    public static object Write(object root, string path, double value) => Write(root, Members(path), 0, value);

    private static object Write(object box, string[] members, int index, double value)
    {
        if (index == members.Length) return value;
        var field = Field(box.GetType(), members[index]);
        var inner = index + 1 == members.Length ? (object)value : Write(field.GetValue(box)!, members, index + 1, value);
        field.SetValue(box, inner);
        return box;
    }

    private static string[] Members(string path) => path.Split('.').Skip(1).ToArray();

    private static FieldInfo Field(Type type, string name) =>
        type.GetField(name, BindingFlags.Public | BindingFlags.Instance)
        ?? throw new InvalidOperationException($"{type.Name} has no public field '{name}'");
}
