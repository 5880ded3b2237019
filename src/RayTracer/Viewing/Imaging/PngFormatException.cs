namespace RayTracer.Viewing.Imaging;

/// <summary>Raised when a PNG stream is malformed or uses a feature the decoder does not support.</summary>
public sealed class PngFormatException : Exception
{
    public PngFormatException(string message) : base(message)
    {
    }

    public PngFormatException(string message, Exception inner) : base(message, inner)
    {
    }
}
