using GMac.Core.CodeGeneration;
using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// The optimizer skips a pass on a block the same pass returned earlier in the run. That is exact
/// only if every pass, run again on its own result, changes nothing: checked here on every pass
/// run while the whole library is generated.
/// </summary>
public sealed class OptimizerPasses_Idempotence
{
    [Fact]
    public void Every_pass_leaves_its_own_result_unchanged_over_the_whole_library()
    {
        var generator = new MacroCodeGenerator(DslProject.Load(RepositoryPaths.DslLibrary));
        var runs = 0;
        var failures = new List<string>();
        var macro = "";
        Optimizer.PassObserver = (pass, result) =>
        {
            runs++;
            var again = pass.Run(result);
            if (!again.HasSameStatements(result) && failures.Count < 5)
                failures.Add($"{macro}: {pass.Name} changed its own result\n{result}\n--- became ---\n{again}");
        };
        try
        {
            foreach (var name in generator.MacroNames.ToArray())
            {
                macro = name;
                var outcome = generator.Generate(name, generator.DefaultBindings(name));
                Assert.True(outcome.Succeeded, $"{name}: {string.Join("; ", outcome.Errors)}");
            }
        }
        finally
        {
            Optimizer.PassObserver = null;
        }
        Assert.True(runs > 1000, $"only {runs} pass runs were seen");
        Assert.True(failures.Count == 0, string.Join("\n\n", failures));
    }
}
