namespace Twister.Tessellation;

/// <summary>A point (u, v) of a surface's parameter square; tessellated meshes use it as texture coordinates.</summary>
public readonly record struct SurfaceParameter(double U, double V);
