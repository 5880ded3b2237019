using System.Diagnostics.CodeAnalysis;
using RayTracer.Scenes;
using RayTracer.Scenes.Cameras;
using RayTracer.Scenes.Gpcm;
using RayTracer.Scenes.Instancing;
using RayTracer.Scenes.Lighting;
using RayTracer.Scenes.Meshes;
using RayTracer.Scenes.Primitives;
using RayTracer.Scenes.Showcase;
using RayTracer.Scenes.Surfaces;
using RayTracer.Scenes.Texturing;
using RayTracer.Scenes.Twister;

namespace RayTracer.Factories;

/// <summary>Registry of the built-in scenes by command-line name.</summary>
public static class SceneFactory
{
    public const string DefaultSceneName = "spheres";

    private static readonly Func<SceneDescription>[] Constructors =
    [
        () => new ShowcaseScene(),
        () => new UniversalPrimitivesScene(),
        () => new GenericPrimitivesScene(),
        () => new CompoundObjectsScene(),
        () => new BinaryObjectScene(),
        () => new ConstructiveSolidsScene(),
        () => new MeshesScene(),
        () => new PinholeZoomScene(),
        () => new OrthographicScene(),
        () => new ThinLensScene(),
        () => new FisheyeScene(),
        () => new SphericalPanoramaScene(),
        () => new StereoScene(),
        () => new GpcmRectangularScene(),
        () => new GpcmCylindricalScene(),
        () => new GpcmConicScene(),
        () => new GpcmSphericalScene(),
        () => new GpcmFisheyeScene(),
        () => new GpcmLayoutScene("rectangular", 70, 16, 480, 360),
        () => new GpcmLayoutScene("cylindrical", 360, 17, 720, 240),
        () => new GpcmLayoutScene("conic", 360, 19, 720, 240),
        () => new GpcmLayoutScene("spherical", 360, 21, 720, 360),
        () => new GpcmLayoutScene("fisheye", 360, 23, 360, 360),
        () => new PointAndDirectionalScene(),
        () => new AmbientOcclusionScene(),
        () => new RectangleLightScene(),
        () => new DiskLightScene(),
        () => new SphereLightScene(),
        () => new EnvironmentLightScene(),
        () => new MattePhongScene(),
        () => new ReflectiveScene(),
        () => new GlossyScene(),
        () => new TransparentScene(),
        () => new DielectricScene(),
        () => new EmissiveScene(),
        () => new CornellBoxScene(),
        () => new GlobalIlluminationScene(),
        () => new CheckersScene(),
        () => new ImageTextureScene(),
        () => new NoiseTexturesScene(),
        () => new MarbleWoodScene(),
        () => new TransformedTexturesScene(),
        () => new TwisterCylindersScene(),
        () => new TwisterCurvesScene(),
        () => new TwisterHelixesScene(),
        () => new TwisterEpitrochoidsScene(),
        () => new TwisterRoulettesScene(),
        () => new TwisterSurfacesScene(),
        () => new InstancingBlocksScene(),
        () => new InstancingHelixScene(),
        () => new InstancingEpitrochoidScene(),
        () => new InstancingColumnScene(),
    ];

    /// <summary>Fresh instances of every scene, in listing order.</summary>
    public static IReadOnlyList<SceneDescription> All => Constructors.Select(c => c()).ToArray();

    public static IEnumerable<string> Names => All.Select(s => s.Name);

    public static bool TryCreate(string name, [NotNullWhen(true)] out SceneDescription? scene)
    {
        foreach (var create in Constructors)
        {
            var candidate = create();
            if (string.Equals(candidate.Name, name, StringComparison.OrdinalIgnoreCase))
            {
                scene = candidate;
                return true;
            }
        }
        scene = null;
        return false;
    }
}
