using RayTracer.Integrators;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Surfaces;

/// <summary>The Cornell box with explicit direct lighting at the first hit plus path-traced indirect light (less noise).</summary>
public sealed class GlobalIlluminationScene : CornellBoxScene
{
    public override string Name => "global-trace";
    public override string Description => "Cornell box with the global tracer (sampled direct light + path-traced indirect).";
    public override int DefaultSamples => 36;

    protected override Integrator CreateIntegrator(World world) => new GlobalIntegrator(world);
}
