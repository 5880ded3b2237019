using System.Reflection;
using System.Runtime.CompilerServices;

namespace GMac.Benchmarks.Reporting;

/// <summary>
/// Moves where the JIT puts the code compiled after it. A loop of a nanosecond measured 0.77, 0.96 or
/// 1.25 of an equivalent loop depending only on where the two landed, and a fresh process places them
/// the same way every time for a given compile order: repeating it samples one placement. Compiling the
/// first <c>n</c> methods of GMac.Core beforehand, a different <c>n</c> in each process, samples others.
/// </summary>
public static class CodePlacement
{
    public static void Shift(int methods)
    {
        const BindingFlags all = BindingFlags.Static | BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;
        var compiled = typeof(GMac.Core.CodeGeneration.CodeBlock).Assembly.GetTypes()
            .Where(t => !t.ContainsGenericParameters)
            .SelectMany(t => t.GetMethods(all))
            .Where(m => !m.IsAbstract && !m.ContainsGenericParameters && m.GetMethodBody() is not null)
            .OrderBy(m => m.MetadataToken)
            .Take(methods);
        foreach (var m in compiled) RuntimeHelpers.PrepareMethod(m.MethodHandle);
    }
}
