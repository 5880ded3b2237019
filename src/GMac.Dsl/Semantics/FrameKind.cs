namespace GMac.Dsl.Semantics;

public enum FrameKind
{
    Euclidean,
    InnerProductMatrix,
    Signature,
    Orthogonalized,
    SubspaceOf,
    TransformedByBcm,
}
