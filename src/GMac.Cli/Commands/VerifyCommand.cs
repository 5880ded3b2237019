using System.CommandLine;
using GMac.CSharp.BindingPoints;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac verify [PATH…] --dsl DIR|FILE… [--seed N] [--cache DIR] [--scalar TYPE] [--fma]</c>: compiles the code of every binding
/// point inside its file and project, and compares it with the numeric engine on random inputs.
/// </summary>
internal static class VerifyCommand
{
    public static Command Create()
    {
        var paths = SharedOptions.Paths("C# files or folders whose binding points are verified");
        var dsl = new DslOptions();
        var seed = new Option<int>("--seed") { Description = "seed of the random inputs", HelpName = "N", DefaultValueFactory = _ => 1 };
        var cache = SharedOptions.Cache();
        var scalar = SharedOptions.Scalar("the scalar type the regions were generated in where a binding point has no //GMac.Type line (default: double)");
        var fma = SharedOptions.Fma("the regions were generated with --fma (where a binding point has no //GMac.Fma line)");
        var command = new Command("verify", "Compile each binding point in memory and check it against the numeric engine.") { paths, seed, cache, scalar, fma };
        dsl.AddTo(command);
        UnknownOptions.RejectIn(paths, command);
        command.SetAction(r =>
        {
            var error = r.InvocationConfiguration.Error;
            if (dsl.Resolve(r, error, out var failure) is not { } sources) return failure;
            var context = DslOptions.Load(sources, r.GetValue(cache), error);
            if (context is null) return ExitCodes.Diagnostics;
            context.DefaultScalarType = r.GetValue(scalar)!;
            context.DefaultFusedMultiplyAdd = r.GetValue(fma);
            return SourceVerification.Run(context, SharedOptions.PathsOrCurrent(r.GetValue(paths)), r.GetValue(seed), r.InvocationConfiguration.Output, error) ? ExitCodes.Success : ExitCodes.Diagnostics;
        });
        return command;
    }
}
