namespace GMac.Dsl.Semantics;

public enum TransformKind
{
    Identity,
    AliasOf,
    InverseOf,
    TransposeOf,
    InverseTransposeOf,
    OutermorphismUsingBcm,
    OutermorphismUsingMatrix,
}
