using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// GA kernels written directly against the symbolic engine (as the DSL's macro compiler will),
/// each with its input bindings, for code-generation tests.
/// </summary>
internal static class Kernels
{
    public static readonly Frame E2 = Frame.Euclidean("e2d", 2);
    public static readonly Frame E3 = Frame.Euclidean("e3d", 3);
    public static readonly Frame Cga = Frame.Conformal3D();

    public static Multivector<Scalar> Vector(Frame f, string name, TemporaryRecorder? r) => SymbolicMultivector.VectorVariables(f, name);

    public static Multivector<Scalar> R(TemporaryRecorder? recorder, Multivector<Scalar> m) => recorder?.Record(m) ?? m;

    /// <summary>Inputs "u.e1" → "u.x" style texts for every variable of the listed vectors.</summary>
    public static Dictionary<string, string> VectorInputs(Frame f, params string[] names)
    {
        var map = new Dictionary<string, string>(StringComparer.Ordinal);
        var fields = new[] { "x", "y", "z", "w", "v" };
        foreach (var n in names)
        {
            var i = 0;
            foreach (var b in f.BladesOfGrade(1))
                map[SymbolicMultivector.VariableName(f, n, b)] = $"{n}.{fields[i++]}";
        }
        return map;
    }

    public static SymbolicProgram Outputs(string name, Multivector<Scalar> value, params string[] blades) =>
        new(blades.Select(b => new SymbolicOutput($"{name}.{b}", value[b])));

    public static Dictionary<string, string> OutputTargets(string name, params string[] blades) =>
        blades.ToDictionary(b => $"{name}.{b}", b => $"{name}_{b.Replace("^", "")}", StringComparer.Ordinal);
}
