namespace RayTracer.Geometry.Meshes;

/// <summary>The two STL encodings.</summary>
public enum StlFormat
{
    Ascii,
    Binary,
}
