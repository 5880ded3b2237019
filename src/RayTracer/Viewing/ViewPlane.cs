using RayTracer.Sampling;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Viewing;

/// <summary>Image resolution, pixel geometry, anti-aliasing sampler, tone mapping and recursion limit.</summary>
public sealed class ViewPlane
{
    private int _horizontalResolution = 400;
    private int _verticalResolution = 300;
    private double _gamma = 1.0;

    public int HorizontalResolution
    {
        get => _horizontalResolution;
        set => _horizontalResolution = value > 0 ? value : throw new ArgumentOutOfRangeException(nameof(value), "Width must be positive.");
    }

    public int VerticalResolution
    {
        get => _verticalResolution;
        set => _verticalResolution = value > 0 ? value : throw new ArgumentOutOfRangeException(nameof(value), "Height must be positive.");
    }

    /// <summary>Side of a pixel in view-plane units.</summary>
    public double PixelSize { get; set; } = 1.0;

    /// <summary>Display gamma; the output is radiance^(1/gamma).</summary>
    public double Gamma
    {
        get => _gamma;
        set => _gamma = value > 0 ? value : throw new ArgumentOutOfRangeException(nameof(value), "Gamma must be positive.");
    }

    public GamutMapping GamutMapping { get; set; } = GamutMapping.Clamp;

    /// <summary>The largest <see cref="MaxDepth"/> the command line accepts; deeper rays add nothing visible.</summary>
    public const int DeepestMaxDepth = 100;

    /// <summary>
    /// Default <see cref="MinimumThroughput"/>: a cut path would have to carry almost 400 times the light
    /// of a white pixel to move it by one step of an 8-bit image (1/255).
    /// </summary>
    public const double DefaultMinimumThroughput = 1e-5;

    /// <summary>Deepest recursion level a tracer follows (0 = primary rays only).</summary>
    public int MaxDepth { get; set; } = 5;

    /// <summary>
    /// Rays whose path throughput (the product of the reflectances and transmittances that scale their
    /// radiance) is below this are not traced; 0 traces every ray up to <see cref="MaxDepth"/>.
    /// </summary>
    public double MinimumThroughput { get; set; } = DefaultMinimumThroughput;

    /// <summary>Pixel sampler; one centred sample when null.</summary>
    public Sampler Sampler { get; set; } = new RegularSampler(1);

    public int NumSamples => Sampler.NumSamples;

    /// <summary>
    /// Writes the image atomically in the format named by the extension: PNG tone mapped (gamut mapping,
    /// gamma), HDR as linear radiance.
    /// </summary>
    public void SaveImage(FrameBuffer image, string path)
    {
        switch (Path.GetExtension(path).ToLowerInvariant())
        {
            case ".png":
                ImageFile.SavePng(image.ToImage(this), path);
                break;
            case ".hdr":
                ImageFile.SaveHdr(image.ToRadianceImage(), path);
                break;
            default:
                throw new ArgumentException(
                    $"cannot write '{path}': the extension must be one of {string.Join(", ", ImageFile.OutputExtensions)}", nameof(path));
        }
    }

    /// <summary>Multi-jittered sampling with <paramref name="samples"/> per pixel (a single sample is the pixel centre).</summary>
    public void SetSamples(int samples) =>
        Sampler = samples <= 1 ? new RegularSampler(1) : new MultiJitteredSampler(samples, seed: SamplerSeeds.Pixel);
}
