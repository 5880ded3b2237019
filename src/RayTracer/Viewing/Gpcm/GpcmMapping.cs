namespace RayTracer.Viewing;

/// <summary>How a generalized pinhole camera maps the view plane to surface parameters (thesis Figure 6-15).</summary>
public enum GpcmMapping
{
    /// <summary>u across the image width from the left edge, v up the height from the bottom edge.</summary>
    Rectangular,

    /// <summary>
    /// On the ellipse inscribed in the image: u the angle from image-right towards image-up in turns
    /// ([0, 1)), v the distance from the centre (1 on the ellipse). Outside the ellipse nothing is seen.
    /// </summary>
    Polar,
}
