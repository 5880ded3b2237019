using System.CommandLine;
using System.CommandLine.Parsing;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Emit;
using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Generation;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac show MACRO --dsl DIR|FILE… [--bind …] [--min EXPR=V] [--max EXPR=V] [--stats] [--scalar TYPE] [--fma]</c>:
/// prints the code generated for one macro, with default bindings (<c>u_e1</c>, <c>w_e1</c>, …) unless
/// given; when only inputs are bound, the outputs get the default names.
/// </summary>
internal static class ShowCommand
{
    public static Command Create()
    {
        var macro = new Argument<string>("MACRO") { Description = "the macro whose code is printed" };
        var dsl = new DslOptions();
        Option<string[]>[] specOptions =
        [
            SpecOption("--bind", "NAME=EXPR",
                "a binding, repeatable: u.e1=<u.x> (C# text in <...> inside a scalar expression), angle.1=cr (a bare C# expression; " +
                "a number is a constant), w.e1=<w.x> (an output into an assignable C# target), u=Vector3D:obj (a whole parameter " +
                "through a class binding on the C# object obj); default: u_e1, w_e1, ..."),
            SpecOption("--min", "EXPR=VALUE", "a lower bound on a bound C# expression, repeatable, e.g. --min cr=0"),
            SpecOption("--max", "EXPR=VALUE", "an upper bound on a bound C# expression, repeatable, e.g. --max cr=6.2832"),
        ];
        var stats = SharedOptions.Stats("begin the code with a comment counting its operations");
        var cache = SharedOptions.Cache();
        var scalar = SharedOptions.Scalar("the scalar type of the printed code (default: double)");
        var fma = SharedOptions.Fma("fuse a product into the sum it is added to (Math.FusedMultiplyAdd, Vector256.FusedMultiplyAdd, …)");
        var command = new Command("show", "Print the code generated for one macro.") { macro };
        dsl.AddTo(command);
        UnknownOptions.RejectIn(macro, command);
        foreach (var option in specOptions) command.Options.Add(option);
        command.Options.Add(stats);
        command.Options.Add(cache);
        command.Options.Add(scalar);
        command.Options.Add(fma);
        command.SetAction(r => dsl.Resolve(r, r.InvocationConfiguration.Error, out var failure) is not { } sources ? failure : Run(r.GetValue(macro)!, sources, r.GetValue(cache), SpecsInOrder(r, specOptions), r.GetValue(stats),
            r.GetValue(scalar)!, r.GetValue(fma), r.InvocationConfiguration.Output, r.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>A repeatable binding option whose every value must read as a spec (else a usage error).</summary>
    private static Option<string[]> SpecOption(string name, string helpName, string description)
    {
        var option = new Option<string[]>(name) { Description = description, HelpName = helpName };
        option.Validators.Add(result =>
        {
            foreach (var token in result.Tokens.Where(t => ParseSpec(name, t.Value, 0) is null))
                result.AddError($"cannot read '{name} {token.Value}': expected {name} {helpName}");
        });
        return option;
    }

    /// <summary>The values of the binding options in command-line order, which numbers their specs.</summary>
    private static List<(string Option, string Value)> SpecsInOrder(ParseResult result, IReadOnlyList<Option<string[]>> options)
    {
        var values = new List<(string, string)>();
        var tokens = result.Tokens;
        for (var i = 0; i + 1 < tokens.Count; i++)
        {
            if (tokens[i].Type == TokenType.Option && options.FirstOrDefault(o => o.Name == tokens[i].Value) is { } option)
                values.Add((option.Name, tokens[++i].Value));
        }
        return values;
    }

    private static int Run(string macro, IReadOnlyList<string> dsl, string? cache, List<(string Option, string Value)> values, bool stats, string scalarType,
        bool fma, TextWriter output, TextWriter error)
    {
        // Every value was checked by the option's validator.
        var specs = values.Select((v, i) => ParseSpec(v.Option, v.Value, i + 1)!).ToList();
        var context = DslOptions.Load(dsl, cache, error);
        if (context is null) return ExitCodes.Diagnostics;
        // Default bindings get line 0 so their errors are not blamed on a --bind option.
        if (specs.Count == 0 || specs.All(s => s is AssumptionSpec))
            specs.InsertRange(0, context.Generator.DefaultBindings(macro).Select(d => d with { Line = 0 }));
        // Every problem is printed at a DSL position: the cause's when known, else the macro's
        // declaration (or the DSL folder for an unknown macro); --bind options are quoted.
        var macroAt = context.Project.Model.Macros.TryGetValue(macro, out var symbol)
            ? symbol.Declaration
            : SourceSpan.None(dsl[0]);
        GenerationOutcome outcome;
        string? code;
        (DiagnosticDescriptor Descriptor, string Message)? problem;
        try
        {
            // The specs come from options, not a file: their "line" is the option's number.
            (outcome, code, problem) = MacroGeneration.GenerateCode(context, macro, specs, 0, filePath: "", generated => new CSharpEmitOptions
            {
                NewLine = Environment.NewLine,
                IncludeStatistics = stats,
                ScalarType = scalarType,
                FusedMultiplyAdd = fma,
                // Outputs no --bind names get default names, declared as the region would declare them.
                DeclareOutputs = generated.Plan?.DefaultOutputs ?? false,
                MayOverwrite = BindingExpressions.Overwrites(generated.Result!.Block),
            });
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            error.WriteLine(new Diagnostic(DiagnosticCodes.InternalError, macroAt, $"internal error while generating '{macro}': {e.GetType().Name}: {e.Message}"));
            return ExitCodes.Diagnostics;
        }
        if (!outcome.Succeeded)
        {
            foreach (var e in outcome.Errors)
            {
                var line = e.Span.Line;
                var option = line > 0 && line <= values.Count ? $"{values[line - 1].Option} {values[line - 1].Value}: " : "";
                error.WriteLine(new Diagnostic(e.Descriptor, e.Cause ?? macroAt, option + e.Message));
            }
            return ExitCodes.Diagnostics;
        }
        if (problem is { } p)
        {
            error.WriteLine(new Diagnostic(p.Descriptor, macroAt, p.Message));
            return ExitCodes.Diagnostics;
        }
        output.Write(code);
        return ExitCodes.Success;
    }

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
            return colon <= 0 || colon == value.Length - 1 ? null : BindingValueReader.ClassBinding(name, value[..colon].Trim(), value[(colon + 1)..].Trim(), index, 1);
        }
        if (dot == 0 || dot == name.Length - 1) return null;
        return new CoefficientBindingSpec(name[..dot], name[(dot + 1)..], BindingValueReader.ReadCommandLine(value), index, 1);
    }
}
