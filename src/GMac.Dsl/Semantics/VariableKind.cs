namespace GMac.Dsl.Semantics;

public enum VariableKind
{
    Input,
    Output,
    Temporary,
}
