using System.Reflection;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace GMac.CSharp.Tests.Support;

/// <summary>The code <c>gmac show</c> prints for some bindings, compiled into a method over a struct V of x, y, z.</summary>
internal sealed class ShownKernel(MethodInfo run, Type vector)
{
    public static ShownKernel Compile(string macro, string[] binds, string method)
    {
        var (exit, code, err) = Tool.Run(["show", macro, "--dsl", SharedDsl.DslDirectory, .. binds.SelectMany(b => new[] { "--bind", b })]);
        Assert.True(exit == 0, err);
        return Load($"public struct V {{ public double x, y, z; }}\npublic static class Kernel {{ {method.Replace("CODE", code)} }}");
    }

    /// <summary>Compiles a source with a struct V and a class Kernel whose Run returns V[].</summary>
    public static ShownKernel Load(string source)
    {
        var compilation = CSharpCompilation.Create("InPlace" + Guid.NewGuid().ToString("N"),
            [CSharpSyntaxTree.ParseText(source)],
            ((string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES")!).Split(Path.PathSeparator).Select(p => MetadataReference.CreateFromFile(p)),
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary));
        using var stream = new MemoryStream();
        var emitted = compilation.Emit(stream);
        Assert.True(emitted.Success, string.Join("\n", emitted.Diagnostics) + "\n" + source);
        var assembly = Assembly.Load(stream.ToArray());
        return new ShownKernel(assembly.GetType("Kernel")!.GetMethod("Run")!, assembly.GetType("V")!);
    }

    public double[][] Run(params double[][] vectors)
    {
        var result = (Array)run.Invoke(null, vectors.Select(ToV).ToArray())!;
        return result.Cast<object>().Select(v => new[] { "x", "y", "z" }.Select(n => (double)vector.GetField(n)!.GetValue(v)!).ToArray()).ToArray();
    }

    private object ToV(double[] c)
    {
        var v = Activator.CreateInstance(vector)!;
        vector.GetField("x")!.SetValue(v, c[0]);
        vector.GetField("y")!.SetValue(v, c[1]);
        vector.GetField("z")!.SetValue(v, c[2]);
        return v;
    }
}
