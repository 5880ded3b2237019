namespace GMac.CSharp.BindingPoints;

/// <summary>
/// What the scope of a binding point says about its names, for deciding aliasing on syntax:
/// <see cref="ReferenceParameters"/> (ref, in and out parameters, pointer and span parameters) may
/// refer to any storage but this member's locals; <see cref="ReferenceLocals"/> (ref locals, pointers,
/// spans, ref or pointer fields) to any storage at all; <see cref="Locals"/> (plain locals and
/// by-value parameters) are storage of their own. Names in none of these are fields: their own storage.
/// </summary>
public sealed record StorageNames(IReadOnlySet<string> ReferenceParameters, IReadOnlySet<string> ReferenceLocals, IReadOnlySet<string> Locals)
{
    public static StorageNames None { get; } = new(new HashSet<string>(), new HashSet<string>(), new HashSet<string>());

    /// <summary>Whether storage reached through the two different names may be the same.</summary>
    public bool MayShare(string a, string b)
    {
        if (ReferenceLocals.Contains(a) || ReferenceLocals.Contains(b)) return true;
        bool IsLocal(string n) => Locals.Contains(n) && !ReferenceParameters.Contains(n);
        if (ReferenceParameters.Contains(a)) return !IsLocal(b);
        if (ReferenceParameters.Contains(b)) return !IsLocal(a);
        return false;
    }
}
