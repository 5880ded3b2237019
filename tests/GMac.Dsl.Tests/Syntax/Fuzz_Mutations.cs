using Antlr4.Runtime;
using GMac.Dsl.Syntax.Generated;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Syntax;

/// <summary>
/// Mutates the library's files token by token (drop, insert, swap, truncate) and
/// checks that parsing and binding never throw or hang, and that every problem
/// comes back as a diagnostic with a position.
/// </summary>
public sealed class Fuzz_Mutations
{
    private const int CasesPerFile = 250;
    private static readonly TimeSpan HangLimit = TimeSpan.FromSeconds(20);

    public static TheoryData<string> LibraryFiles()
    {
        var data = new TheoryData<string>();
        foreach (var path in Directory.GetFiles(RepositoryPaths.DslLibrary, "*.gmac", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
            data.Add(Path.GetRelativePath(RepositoryPaths.DslLibrary, path));
        return data;
    }

    [Theory]
    [MemberData(nameof(LibraryFiles))]
    public async Task Mutated_file_yields_positioned_diagnostics_not_exceptions(string relativePath)
    {
        var library = Directory.GetFiles(RepositoryPaths.DslLibrary, "*.gmac", SearchOption.AllDirectories)
            .Order(StringComparer.Ordinal)
            .ToDictionary(p => Path.GetRelativePath(RepositoryPaths.DslLibrary, p), File.ReadAllText);
        var original = library[relativePath];
        var tokens = Tokens(original);
        var random = new Random(relativePath.Aggregate(17, (h, c) => h * 31 + c));
        // The file under test is mutated; the frames and classes it needs stay intact.
        var context = library.Where(kv => kv.Key != relativePath && !kv.Key.StartsWith("macros", StringComparison.Ordinal))
            .Select(kv => (kv.Key, kv.Value)).ToList();

        var failures = 0;
        for (var i = 0; i < CasesPerFile; i++)
        {
            var mutated = Mutate(original, tokens, random);
            var sources = context.Append((relativePath, mutated)).ToList();
            var run = Task.Run(() => DslProject.FromSources(sources));
            var finished = await Task.WhenAny(run, Task.Delay(HangLimit));
            Assert.True(finished == run, $"case {i} did not finish:\n{mutated}");
            var project = await run;
            foreach (var d in project.Diagnostics)
            {
                Assert.False(string.IsNullOrEmpty(d.Span.FilePath));
                Assert.True(d.Span.Line >= 1 && d.Span.Column >= 1, $"case {i}: {d}");
                Assert.StartsWith("GMAC", d.Code);
            }
            if (project.HasErrors) failures++;
        }
        // Most mutations break something; a fuzzer whose cases all pass tests nothing.
        Assert.True(failures > CasesPerFile / 4, $"only {failures} of {CasesPerFile} mutations produced errors");
    }

    [Fact]
    public void Truncation_at_every_token_never_throws()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryPaths.DslLibrary, "macros", "normals.gmac"));
        var frames = File.ReadAllText(Path.Combine(RepositoryPaths.DslLibrary, "frames.gmac"));
        foreach (var token in Tokens(text))
        {
            var project = DslProject.FromSources([("frames.gmac", frames), ("cut.gmac", text[..token.StartIndex])]);
            Assert.All(project.Diagnostics, d => Assert.True(d.Span.Line >= 1 && d.Span.Column >= 1));
        }
    }

    private static List<IToken> Tokens(string text)
    {
        var lexer = new GMacDslLexer(new AntlrInputStream(text));
        lexer.RemoveErrorListeners();
        return lexer.GetAllTokens().Where(t => t.Channel == TokenConstants.DefaultChannel).Cast<IToken>().ToList();
    }

    private static string Mutate(string text, List<IToken> tokens, Random random)
    {
        var edits = 1 + random.Next(3);
        var result = text;
        for (var e = 0; e < edits; e++)
        {
            var current = Tokens(result);
            if (current.Count == 0) break;
            var t = current[random.Next(current.Count)];
            var span = (t.StartIndex, Length: t.StopIndex - t.StartIndex + 1);
            switch (random.Next(5))
            {
                case 0: // drop a token
                    result = result.Remove(span.StartIndex, span.Length);
                    break;
                case 1: // insert a token taken from elsewhere in the original
                    result = result.Insert(span.StartIndex, tokens[random.Next(tokens.Count)].Text + " ");
                    break;
                case 2: // swap with the next token
                {
                    var index = current.IndexOf(t);
                    if (index + 1 >= current.Count) break;
                    var u = current[index + 1];
                    var uLength = u.StopIndex - u.StartIndex + 1;
                    result = result.Remove(u.StartIndex, uLength).Insert(u.StartIndex, t.Text)
                        .Remove(span.StartIndex, span.Length).Insert(span.StartIndex, u.Text);
                    break;
                }
                case 3: // truncate
                    result = result[..span.StartIndex];
                    break;
                default: // replace with a stray character
                    result = result.Remove(span.StartIndex, span.Length).Insert(span.StartIndex, "#@$\"'`?!~"[random.Next(9)].ToString());
                    break;
            }
        }
        return result;
    }
}
