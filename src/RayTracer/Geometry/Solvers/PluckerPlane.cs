namespace RayTracer.Geometry.Solvers;

/// <summary>A plane as the projective trivector of three of its points (binding PluckerPlane in dsl/).</summary>
public struct PluckerPlane
{
    public double xyz;
    public double xyo;
    public double yzo;
    public double xzo;
}
