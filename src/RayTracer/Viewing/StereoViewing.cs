namespace RayTracer.Viewing;

/// <summary>How a stereo pair is laid out: left eye image on the left (parallel) or on the right (cross-eyed).</summary>
public enum StereoViewing
{
    Parallel,
    Transverse,
}
