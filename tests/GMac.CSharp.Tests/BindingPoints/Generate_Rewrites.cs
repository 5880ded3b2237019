using System.Text;
using System.Text.RegularExpressions;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.Dsl;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary><c>gmac generate</c> on copies of C# files: what it writes, and that a second run writes nothing.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_Rewrites : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    // §4.10.1: the normal to two vectors held in separate variables, one coefficient per line.
    private const string NormalFile = """
        namespace Sample;

        public static class Normals
        {
            public static (double, double, double) Get(double ux, double uy, double uz, double vx, double vy, double vz)
            {
                double wx, wy, wz;
                #region GMac : GetNormalToVectors
                //GMac.Bind("u.e1", ux);
                //GMac.Bind("u.e2", uy);
                //GMac.Bind("u.e3", uz);
                //GMac.Bind("v.e1", "<vx>");
                //GMac.Bind("v.e2", "<vy>");
                //GMac.Bind("v.e3", "<vz>");
                //GMac.Bind("w.e1", wx);
                //GMac.Bind("w.e2", "<wy>");
                //GMac.Bind("w.e3", wz);   // the comment after the call is allowed
                stale text that the generator replaces
                #endregion
                return (wx, wy, wz);
            }
        }
        """;

    private static string[] RegionBody(string text, string macro)
    {
        var lines = text.Split('\n').Select(l => l.TrimEnd('\r')).ToList();
        var start = lines.FindIndex(l => l.Trim() == $"#region GMac : {macro}");
        var end = lines.FindIndex(start, l => l.Trim() == "#endregion");
        return lines.Skip(start + 1).Take(end - start - 1).Where(l => !l.TrimStart().StartsWith("//GMac.", StringComparison.Ordinal)).ToArray();
    }

    /// <summary>The Figure 6-6 twist as a stand-alone file with one binding point.</summary>
    private const string TwistSample = "tests/GMac.CSharp.Tests/BindingPoints/Samples/Twist.cs.txt";

    [Fact]
    public void Thesis_normal_to_vectors_is_three_assignments_with_six_products_and_three_subtractions()
    {
        var path = _temp.Write("Normals.cs", NormalFile);
        var (exit, _, err) = Tool.Generate([_temp.Path]);
        Assert.True(exit == 0, err);
        var body = RegionBody(File.ReadAllText(path), "GetNormalToVectors");
        Assert.Equal(3, body.Length);
        Assert.All(body, l => Assert.Matches(@"^\s+w[xyz] = [^;]+;$", l));
        Assert.Equal(6, body.Sum(l => l.Count(c => c == '*')));
        Assert.Equal(3, body.Sum(l => Regex.Matches(l.Split('=')[1], @"[+-]").Count));
        // indented like the region, and the cross product it must be
        var regionIndent = File.ReadAllLines(path).Single(l => l.Contains("#region GMac", StringComparison.Ordinal)).Replace("#region GMac : GetNormalToVectors", "");
        Assert.All(body, l => Assert.StartsWith(regionIndent + "w", l, StringComparison.Ordinal));
        Assert.Contains(body, l => l.Trim() is "wx = uy * vz - uz * vy;" or "wx = -(uz * vy) + uy * vz;" or "wx = uy * vz - vy * uz;" or "wx = vz * uy - uz * vy;");
    }

    [Fact]
    public void Stats_flag_adds_a_header_with_the_counts()
    {
        var path = _temp.Write("Normals.cs", NormalFile);
        var (exit, _, err) = Tool.Generate([_temp.Path], stats: true);
        Assert.True(exit == 0, err);
        var body = RegionBody(File.ReadAllText(path), "GetNormalToVectors");
        Assert.StartsWith("// GMac: 3 additions/subtractions, 6 multiplications, 0 divisions, 0 function calls, 0 temporaries", body[0].Trim(), StringComparison.Ordinal);
    }

    [Fact]
    public void Second_run_changes_no_byte()
    {
        var path = _temp.Write("Normals.cs", NormalFile);
        var twist = _temp.Write("sub/Twist.cs", File.ReadAllText(Path.Combine(SharedDsl.RepositoryRoot, TwistSample)));
        Assert.Equal(0, Tool.Generate([_temp.Path]).Exit);
        var first = (File.ReadAllBytes(path), File.ReadAllBytes(twist));
        var stamp = File.GetLastWriteTimeUtc(path);

        var (exit, output, _) = Tool.Generate([_temp.Path]);

        Assert.Equal(0, exit);
        Assert.Contains("0 file(s) changed", output);
        Assert.Equal(first.Item1, File.ReadAllBytes(path));
        Assert.Equal(first.Item2, File.ReadAllBytes(twist));
        Assert.Equal(stamp, File.GetLastWriteTimeUtc(path));
    }

    [Fact]
    public void Line_endings_and_byte_order_mark_are_kept()
    {
        var path = Path.Combine(_temp.Path, "Normals.cs");
        var crlf = NormalFile.Replace("\r\n", "\n").Replace("\n", "\r\n");
        File.WriteAllText(path, crlf, new UTF8Encoding(encoderShouldEmitUTF8Identifier: true));

        Assert.Equal(0, Tool.Generate([path]).Exit);

        var bytes = File.ReadAllBytes(path);
        Assert.Equal([0xEF, 0xBB, 0xBF], bytes[..3]);
        var text = Encoding.UTF8.GetString(bytes, 3, bytes.Length - 3);
        Assert.DoesNotMatch("[^\r]\n", text);
        Assert.DoesNotContain("stale text", text);
        Assert.Contains("wx = ", text);
    }

    [Fact]
    public void Temporaries_avoid_every_identifier_of_the_file()
    {
        var source = File.ReadAllText(Path.Combine(SharedDsl.RepositoryRoot, TwistSample))
            .Replace("var ct = Translation;", "var ct = Translation; var tmp0 = 0.0; var gmacTmp3 = tmp0;");
        var path = _temp.Write("Twist.cs", source);

        Assert.Equal(0, Tool.Generate([path]).Exit);

        var body = RegionBody(File.ReadAllText(path), "ApplyTwistToPoint3D");
        Assert.DoesNotContain(body, l => l.Contains("double tmp", StringComparison.Ordinal) || l.Contains("double gmacTmp", StringComparison.Ordinal));
        Assert.Contains(body, l => l.TrimStart().StartsWith("double ", StringComparison.Ordinal));
    }

    [Fact]
    public void Bin_and_obj_folders_are_skipped()
    {
        var inBin = _temp.Write("bin/Normals.cs", NormalFile);
        var inObj = _temp.Write("obj/Debug/Normals.cs", NormalFile);

        var (exit, output, _) = Tool.Generate([_temp.Path]);

        Assert.Equal(0, exit);
        Assert.Contains("0 file(s) scanned", output);
        Assert.Equal(NormalFile, File.ReadAllText(inBin));
        Assert.Equal(NormalFile, File.ReadAllText(inObj));
    }

    [Fact]
    public void Check_is_clean_after_generate_and_fails_after_a_dsl_edit_that_changes_the_code()
    {
        var dsl = Path.Combine(_temp.Path, "dsl");
        foreach (var file in Directory.EnumerateFiles(SharedDsl.DslDirectory, "*.gmac", SearchOption.AllDirectories))
        {
            var target = Path.Combine(dsl, Path.GetRelativePath(SharedDsl.DslDirectory, file));
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            File.Copy(file, target);
        }
        var code = Path.Combine(_temp.Path, "code");
        var path = Path.Combine(code, "Normals.cs");
        Directory.CreateDirectory(code);
        File.WriteAllText(path, NormalFile);
        var context = new GenerationContext(DslProject.Load(dsl), null);
        Assert.Equal(0, Tool.Generate([code], context: context).Exit);
        var generated = File.ReadAllBytes(path);

        Assert.Equal(0, Tool.Generate([code], check: true, context: context).Exit);

        var normals = Path.Combine(dsl, "macros", "normals.gmac");
        File.WriteAllText(normals, File.ReadAllText(normals).Replace("w = t1 lcp e3d.Ii;", "w = t1 lcp e3d.I;"));
        var edited = new GenerationContext(DslProject.Load(dsl), null);
        var (exit, _, err) = Tool.Generate([code], check: true, context: edited);

        Assert.Equal(1, exit);
        Assert.Matches(@"Normals\.cs\(8,9\): error GMAC0410: binding point 'GetNormalToVectors' is out of date", err);
        Assert.Equal(generated, File.ReadAllBytes(path));
    }

    [Fact]
    public void Two_regions_in_one_method_get_distinct_temporaries_and_the_result_compiles_in_the_verifier()
    {
        var twist = File.ReadAllText(Path.Combine(SharedDsl.RepositoryRoot, TwistSample));
        var start = twist.IndexOf("        #region GMac", StringComparison.Ordinal);
        var end = twist.IndexOf("#endregion", start, StringComparison.Ordinal) + "#endregion\n".Length;
        var region = twist[start..end];
        var twice = twist.Insert(end, region.Replace("\"out_mv\", \"Vector3D\", result", "\"out_mv\", \"Vector3D\", result2")).Replace("var result = new TwistablePoint();", "var result = new TwistablePoint(); var result2 = result;");
        var path = _temp.Write("Twist.cs", twice);

        Assert.Equal(0, Tool.Generate([path]).Exit);

        var text = File.ReadAllText(path);
        var declared = Regex.Matches(text, @"double (\w+) =").Select(m => m.Groups[1].Value).ToList();
        Assert.True(declared.Count > 0);
        Assert.Equal(declared.Count, declared.Distinct().Count());
    }
}
