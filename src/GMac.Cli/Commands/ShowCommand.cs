using GMac.Cli.BindingPoints;
using GMac.Core.CodeGeneration;
using GMac.Core.Numerics;
using GMac.Dsl.Generation;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac show MACRO --dsl DIR [--bind …] [--min EXPR=V] [--max EXPR=V] [--stats]</c>: prints the
/// code generated for one macro, with default bindings (<c>u_e1</c>, <c>w_e1</c>, …) unless given.
/// </summary>
internal sealed class ShowCommand : ICommand
{
    private static readonly HashSet<string> FlagNames = ["--stats"];
    private static readonly HashSet<string> ValuedNames = ["--bind", "--min", "--max"];

    public string Name => "show";
    public string Summary => "print the code generated for one macro";

    public string Usage =>
        "gmac show MACRO --dsl DIR [--bind NAME=EXPR ...] [--min EXPR=VALUE] [--max EXPR=VALUE] [--stats] [--cache DIR]" + Environment.NewLine +
        "  --bind u.e1=<u.x>       coefficient from a C# expression (<...> marks C# text inside a scalar expression)" + Environment.NewLine +
        "  --bind angle.1=cr       coefficient from a bare C# expression (a number is a constant)" + Environment.NewLine +
        "  --bind w.e1=<w.x>       output coefficient into an assignable C# target" + Environment.NewLine +
        "  --bind u=Vector3D:obj   whole parameter through a class binding on the C# object obj" + Environment.NewLine +
        "  --min cr=0 --max cr=6.2832   bounds on a bound C# expression";

    public int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        var problem = CommandOptions.TryParse(args, FlagNames, ValuedNames, out var options);
        if (problem is null && options.Positional.Count != 1) problem = "expected exactly one MACRO name";
        if (problem is not null)
        {
            error.WriteLine($"gmac show: {problem}");
            error.WriteLine($"usage: {Usage}");
            return ExitCodes.Usage;
        }
        var specs = new List<BindingSpec>();
        for (var i = 0; i < options.Values.Count; i++)
        {
            var (option, value) = options.Values[i];
            if (ParseSpec(option, value, i + 1) is { } spec) specs.Add(spec);
            else
            {
                error.WriteLine($"gmac show: cannot read '{option} {value}'");
                error.WriteLine($"usage: {Usage}");
                return ExitCodes.Usage;
            }
        }
        var context = DslLoader.Load(options.Dsl!, options.Cache, error);
        if (context is null) return ExitCodes.Diagnostics;
        var macro = options.Positional[0];
        // Default bindings get line 0 so their errors are not blamed on a --bind option.
        if (specs.Count == 0 || specs.All(s => s is AssumptionSpec))
            specs.InsertRange(0, context.Generator.DefaultBindings(macro).Select(d => d with { Line = 0 }));
        // Every problem is printed at a DSL position: the cause's when known, else the macro's
        // declaration (or the DSL folder for an unknown macro); --bind options are quoted.
        var macroAt = context.Project.Model.Macros.TryGetValue(macro, out var symbol)
            ? symbol.Declaration
            : Dsl.Diagnostics.SourceSpan.None(options.Dsl!);
        GenerationOutcome outcome;
        try
        {
            outcome = BindingTextCheck.Generate(context, macro, specs, 0);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            error.WriteLine(Diagnostic(macroAt, "GMAC0409", $"internal error while generating '{macro}': {e.GetType().Name}: {e.Message}"));
            return ExitCodes.Diagnostics;
        }
        if (!outcome.Succeeded)
        {
            foreach (var e in outcome.Errors)
            {
                var option = e.Line > 0 && e.Line <= options.Values.Count ? $"{options.Values[e.Line - 1].Option} {options.Values[e.Line - 1].Value}: " : "";
                error.WriteLine(Diagnostic(e.Source ?? macroAt, e.Code, option + e.Message));
            }
            return ExitCodes.Diagnostics;
        }
        output.Write(CSharpEmitter.Emit(outcome.Result!.Block, new CSharpEmitOptions
        {
            NewLine = Environment.NewLine,
            IncludeStatistics = options.Flags.Contains("--stats"),
        }));
        return ExitCodes.Success;
    }

    private static string Diagnostic(Dsl.Diagnostics.SourceSpan at, string code, string message) =>
        $"{at.FilePath}({at.Line},{at.Column}): error {code}: {message}";

    /// <summary>One <c>--bind</c>, <c>--min</c> or <c>--max</c>; the spec's line is its position among them.</summary>
    private static BindingSpec? ParseSpec(string option, string text, int index)
    {
        var eq = text.IndexOf('=');
        if (eq <= 0 || eq == text.Length - 1) return null;
        var name = text[..eq].Trim();
        var value = text[(eq + 1)..].Trim();
        if (option is "--min" or "--max")
            return Rational.TryParse(value, out var bound) ? new AssumptionSpec(name, bound, option == "--min", index, 1) : null;
        var dot = name.IndexOf('.');
        if (dot < 0)
        {
            var colon = value.IndexOf(':');
            return colon <= 0 || colon == value.Length - 1 ? null : new ClassBindingSpec(name, value[..colon].Trim(), value[(colon + 1)..].Trim(), index, 1);
        }
        if (dot == 0 || dot == name.Length - 1) return null;
        return new CoefficientBindingSpec(name[..dot], name[(dot + 1)..], value, value.Contains('<'), index, 1);
    }
}
