using System.Collections.Concurrent;
using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// <c>gmac generate</c> shares one generator between threads. Generating the whole library on
/// several threads at once must give, macro for macro, the block one thread gives.
/// </summary>
public sealed class MacroCodeGenerator_Concurrency
{
    [Fact]
    public void Generating_the_library_on_several_threads_gives_the_code_of_one_thread()
    {
        var project = DslProject.Load(RepositoryPaths.DslLibrary);
        var names = new MacroCodeGenerator(project).MacroNames.ToArray();

        // concurrent first, so it does not find the other run's results in the shared memos
        var shared = new MacroCodeGenerator(project);
        var concurrent = new ConcurrentDictionary<string, string>(StringComparer.Ordinal);
        Parallel.ForEach(names, new ParallelOptions { MaxDegreeOfParallelism = 4 }, name =>
            concurrent[name] = Text(shared.Generate(name, shared.DefaultBindings(name))));

        var single = new MacroCodeGenerator(project);
        var differing = names.Where(name => Text(single.Generate(name, single.DefaultBindings(name))) != concurrent[name]).ToList();
        Assert.True(names.Length > 100, $"only {names.Length} macros");
        Assert.True(differing.Count == 0, $"differ when generated concurrently: {string.Join(", ", differing)}");
    }

    private static string Text(GenerationOutcome outcome) =>
        outcome.Succeeded ? outcome.Result!.Block.ToString() : "errors: " + string.Join("; ", outcome.Errors);
}
