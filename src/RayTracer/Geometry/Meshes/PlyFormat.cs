namespace RayTracer.Geometry.Meshes;

/// <summary>The three encodings of the PLY body.</summary>
public enum PlyFormat
{
    Ascii,
    BinaryLittleEndian,
    BinaryBigEndian,
}
