namespace GMac.Dsl.Semantics;

public enum CastKind
{
    ToGrades,
    ToSubspace,
    ToClass,
}
