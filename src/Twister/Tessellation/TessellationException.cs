namespace Twister.Tessellation;

/// <summary>A shape that cannot be tessellated as asked: non-finite values, or more elements than the budget.</summary>
public sealed class TessellationException(string message) : Exception(message)
{
}
