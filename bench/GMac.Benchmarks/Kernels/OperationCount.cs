namespace GMac.Benchmarks.Kernels;

/// <summary>
/// Arithmetic operations of one kernel item, counted like <c>CodeStatistics</c>: a subtraction is an
/// addition, a multiplication by a constant counts, a negation does not, a function call is one operation.
/// </summary>
public sealed record OperationCount(int Additions, int Multiplications, int Divisions, int Calls)
{
    public int Total => Additions + Multiplications + Divisions + Calls;

    public override string ToString() => $"{Total} ({Additions} add, {Multiplications} mul, {Divisions} div, {Calls} call)";
}
