namespace RayTracer.Viewing;

/// <summary>How radiance above 1 in some channel is brought into the displayable range.</summary>
public enum GamutMapping
{
    /// <summary>Each channel is clipped to 1 independently (can shift hue).</summary>
    Clamp,

    /// <summary>The colour is divided by its largest component, keeping hue.</summary>
    MaxToOne,

    /// <summary>Out-of-gamut pixels are painted a marker colour (red) for diagnosis.</summary>
    Highlight,
}
