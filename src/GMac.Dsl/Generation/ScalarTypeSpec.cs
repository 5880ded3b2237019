namespace GMac.Dsl.Generation;

/// <summary>
/// <c>//GMac.Type("float");</c>: the scalar type the binding point's code is written in, as the
/// user spelled it (checked where the code is emitted; <c>double</c> when the line is absent).
/// </summary>
public sealed record ScalarTypeSpec(string TypeName, int Line, int Column) : BindingSpec(Line, Column);
