namespace RayTracer.Viewing.Imaging;

/// <summary>An image file that cannot be read: missing, unreadable, malformed or of an unknown format.</summary>
public sealed class ImageFormatException : Exception
{
    public ImageFormatException(string path, string problem, Exception? inner = null)
        : base($"{path}: {problem}", inner)
    {
        Path = path;
        Problem = problem;
    }

    /// <summary>The file as the user named it.</summary>
    public string Path { get; }

    public string Problem { get; }
}
