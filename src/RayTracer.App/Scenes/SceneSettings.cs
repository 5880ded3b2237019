namespace RayTracer.Scenes;

/// <summary>Overrides a user may give when building a scene; null keeps the scene's own choice.</summary>
public sealed record SceneSettings
{
    public int? Width { get; init; }
    public int? Height { get; init; }
    public int? SamplesPerPixel { get; init; }
    public int? MaxDepth { get; init; }

    /// <summary>PNG for scenes that show an image texture (<see cref="SceneDescription.UsesImage"/>).</summary>
    public string? ImagePath { get; init; }
}
