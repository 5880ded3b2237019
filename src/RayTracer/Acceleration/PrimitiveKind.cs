namespace RayTracer.Acceleration;

/// <summary>How a primitive table tests primitive i: through its virtual methods or with one of the inline triangle tests.</summary>
internal enum PrimitiveKind : byte
{
    Object,
    MollerTrumbore,
    Algebraic,
    Plucker,
    PluckerEdges,
}
