using GMac.Benchmarks.Generation;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Tests.Support;
using GMac.Dsl;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Tests.Generation;

/// <summary>The report reads the kernels' regions with gmac's reader: the right bindings of the right regions.</summary>
public class KernelRegions_Read
{
    [Fact]
    public void Class_and_coefficient_bindings_are_read_with_their_lines()
    {
        const string source = """
            class K
            {
                void M()
                {
                    #region GMac : Other
                    //GMac.Bind("x.e1", "<a>");
                    #endregion
                    #region GMac : Target
                    //GMac.Bind("p", "Vector3D", "obj.P");
                    //GMac.Bind("q.e1^e2", "<o.x>");
                    //GMac.Bind("s.1", "2");
                    y = 1;
                    #endregion
                }
            }
            """;
        var regions = KernelRegions.Read("K.cs", source, "Target");
        var bindings = Assert.Single(regions);
        Assert.Equal(3, bindings.Count);
        var c = Assert.IsType<ClassBindingSpec>(bindings[0]);
        Assert.Equal(("p", "Vector3D", "obj.P", 9), (c.Parameter, c.ClassBinding, c.Target, c.Line));
        var q = Assert.IsType<CoefficientBindingSpec>(bindings[1]);
        Assert.Equal(("q", "e1^e2", "o.x"), (q.Parameter, q.Blade, q.Value.Target));
        // A quoted value is a template, as gmac reads it, even without <...>.
        var s = Assert.IsType<CoefficientBindingSpec>(bindings[2]);
        Assert.IsType<TemplateValue>(s.Value);
    }

    [Fact]
    public void A_line_gmac_rejects_stops_the_report_with_its_position()
    {
        const string source = "class K\n{\n    void M()\n    {\n        #region GMac : Target\n        //GMac.Bnd(\"u.e1\", \"<a>\");\n        #endregion\n    }\n}\n";
        var e = Assert.Throws<FormatException>(() => KernelRegions.Read("K.cs", source, "Target"));
        Assert.StartsWith("line 6, column 9: ", e.Message);
    }

    [Fact]
    public void Every_kernel_source_is_embedded_with_at_least_one_binding_point_of_its_macro()
    {
        foreach (var kernel in KernelCatalog.CreateAll())
            Assert.NotEmpty(KernelRegions.RegionsOf(kernel.GetType().Name, kernel.MacroName));
    }

    [Fact]
    public void Generated_counts_of_the_normal_match_the_cross_product_and_the_sphere_stays_within_100()
    {
        var counter = new GeneratedOperationCounter(new MacroCodeGenerator(DslProject.Load(RepositoryPaths.Dsl)));
        Assert.Equal(new OperationCount(3, 6, 0, 0), counter.Count(new NormalToVectorsKernel()));
        Assert.InRange(counter.Count(new SphereThroughPointsKernel()).Total, 1, 100);
    }
}
