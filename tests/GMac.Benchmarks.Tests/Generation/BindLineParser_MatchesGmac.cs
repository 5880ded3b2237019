using GMac.Benchmarks.Generation;
using GMac.Cli.BindingPoints;

namespace GMac.Benchmarks.Tests.Generation;

/// <summary>
/// The report reads the kernels' binding lines as gmac does: the same specs for the lines gmac
/// accepts (quoted values, bare C#, assumptions) and a failure, with gmac's reason, for a line it rejects.
/// </summary>
public sealed class BindLineParser_MatchesGmac
{
    private static string Source(string lines) => $$"""
        class K
        {
            void M()
            {
                #region GMac : Target
        {{lines}}
                #endregion
            }
        }
        """;

    [Fact]
    public void Quoted_values_bare_targets_and_assumptions_read_as_gmac_reads_them()
    {
        var source = Source("""
                    //GMac.Bind("p", "Vector3D", l.P1);
                    //GMac.Bind("q.e1^e2", "2");
                    //GMac.Bind("s.1", t.Scale * 2);
                    //GMac.Bind("w.e1", @"<o.x>"); // output
                    //GMac.AssumeMin("t.Scale", "-1/2");
                    //GMac.AssumeMax(t.Scale, 6.25);
            """);
        var gmac = BindingPointReader.Read(SourceText.FromString("K.cs", source));
        Assert.Empty(gmac.Diagnostics);
        var expected = Assert.Single(gmac.Points).Specs;
        Assert.Equal(6, expected.Count);

        var bench = Assert.Single(BindLineParser.Parse(source, "Target"));
        Assert.Equal(expected, bench);
    }

    [Theory]
    [InlineData("//GMac.Bind(\"u.e1\", \"<a>\") trailing")]
    [InlineData("//GMac.Bind(\"u\", \"Vector3D\", u")]
    [InlineData("//GMac.Bnd(\"u.e1\", \"<a>\");")]
    [InlineData("//GMac.AssumeMin(\"a\", \"zero\");")]
    public void A_line_gmac_rejects_stops_the_report_with_gmacs_reason(string line)
    {
        var source = Source("            //GMac.Bind(\"v.e1\", \"<b>\");\n            " + line);
        var gmac = BindingPointReader.Read(SourceText.FromString("K.cs", source));
        var diagnostic = Assert.Single(gmac.Diagnostics);
        Assert.Equal("GMAC0404", diagnostic.Code);

        var e = Assert.Throws<FormatException>(() => BindLineParser.Parse(source, "Target"));
        Assert.Contains($"line {diagnostic.Span.Line}, column {diagnostic.Span.Column}: {diagnostic.Message}", e.Message);
    }
}
