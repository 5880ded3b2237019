namespace GMac.Core.Symbolic;

/// <summary>Describes an object to intern without making it: <see cref="WeakInternTable{T}"/> makes it only when no equal one lives.</summary>
internal interface IInternKey<T>
{
    /// <summary>Whether <paramref name="candidate"/> is the object this key describes.</summary>
    bool Describes(T candidate);

    /// <summary>A new object as described.</summary>
    T Create();
}
