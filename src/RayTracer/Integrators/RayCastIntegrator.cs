using RayTracer.Scenes;

namespace RayTracer.Integrators;

/// <summary>
/// Ray casting: the Whitted estimator, used for scenes of opaque, non-mirror surfaces (where no secondary
/// ray is traced) or with a maximum depth of 0.
/// </summary>
public sealed class RayCastIntegrator(World world) : WhittedIntegrator(world);
