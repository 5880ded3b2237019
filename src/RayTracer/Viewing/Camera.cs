using RayTracer.Scenes;

namespace RayTracer.Viewing;

/// <summary>Generates primary rays and renders a world.</summary>
public abstract class Camera
{
    public abstract void RenderScene(World world);
}
