using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// Binding only a macro's inputs: outputs get default names, declared by the generated code, and
/// every class binding of a conformal object reads (or writes) a C# object with blade-named members.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_InputsOnly : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static string Dsl => SharedDsl.DslDirectory;

    private const string Types = """
        namespace Sample;

        public sealed class P3 { public double x, y, z; }
        public sealed class Pt { public double e1, e2, e3, ni; }
        public sealed class DS { public double no, e1, e2, e3, ni; }
        public sealed class DP { public double e1, e2, e3, ni; }
        public sealed class Quad { public double no_e1_e2_e3, no_e1_e2_ni, no_e1_e3_ni, no_e2_e3_ni, e1_e2_e3_ni; }
        public sealed class Tri { public double no_e1_e2, no_e1_e3, no_e1_ni, no_e2_e3, no_e2_ni, no_e3_ni, e1_e2_e3, e1_e2_ni, e1_e3_ni, e2_e3_ni; }
        public sealed class Bi { public double no_e1, no_e2, no_e3, no_ni, e1_e2, e1_e3, e1_ni, e2_e3, e2_ni, e3_ni; }
        public sealed class Ver
        {
            public double s, no_e1, no_e2, no_e3, no_ni, e1_e2, e1_e3, e1_ni, e2_e3, e2_ni, e3_ni;
            public double no_e1_e2_e3, no_e1_e2_ni, no_e1_e3_ni, no_e2_e3_ni, e1_e2_e3_ni;
        }
        public sealed class Rot { public double s, xy, yz, zx; }
        """;

    private const string InputsOnly = """
        namespace Sample;

        public static class InputsOnly
        {
            public static double Distance(Pt a, Pt b)
            {
                #region GMac : SquaredDistance
                //GMac.Bind("p", "NormalizedPoint3D", a);
                //GMac.Bind("q", "NormalizedPoint3D", b);
                #endregion
                return d2_s;
            }

            public static (double, double, double, double) Centre(DS s)
            {
                #region GMac : SphereCentreAndRadius
                //GMac.Bind("omega", "DualSphere3D", s);
                #endregion
                return (centre_e1, centre_e2, centre_e3, squaredRadius_s);
            }

            public static (double, double, double) Rotate(Rot r, P3 v)
            {
                #region GMac : ApplyRotor3D
                //GMac.Bind("r", "Rotor3D", r);
                //GMac.Bind("x", "Vector3D", v);
                #endregion
                return (y_e1, y_e2, y_e3);
            }

            public static (double, double, double) RotateByUnit(Rot r, P3 v)
            {
                #region GMac : ApplyUnitRotor3D
                //GMac.Bind("r", "UnitRotor3D", r);
                //GMac.Bind("x", "Vector3D", v);
                #endregion
                return (y_e1, y_e2, y_e3);
            }

            public static (double, double, double, double) Move(Ver v, Pt a)
            {
                #region GMac : ApplyVersorToPoint
                //GMac.Bind("v", "Versor3D", v);
                //GMac.Bind("p", "NormalizedPoint3D", a);
                #endregion
                return (q_e1, q_e2, q_e3, q_ni);
            }

            public static double Sphere(Pt a, Pt b, Pt c, Pt d)
            {
                #region GMac : SphereThroughPoints
                //GMac.Bind("p1", "NormalizedPoint3D", a);
                //GMac.Bind("p2", "NormalizedPoint3D", b);
                //GMac.Bind("p3", "NormalizedPoint3D", c);
                //GMac.Bind("p4", "NormalizedPoint3D", d);
                #endregion
                return sigma_e1_e2_e3_ni + omega_no;
            }
        }
        """;

    private const string Outputs = """
        namespace Sample;

        public static class Objects
        {
            public static void Sphere(Pt a, Pt b, Pt c, Pt d, Quad sphere, DS dual)
            {
                #region GMac : SphereThroughPoints
                //GMac.Bind("p1", "NormalizedPoint3D", a);
                //GMac.Bind("p2", "NormalizedPoint3D", b);
                //GMac.Bind("p3", "NormalizedPoint3D", c);
                //GMac.Bind("p4", "NormalizedPoint3D", d);
                //GMac.Bind("sigma", "Sphere3D", sphere);
                //GMac.Bind("omega", "DualSphere3D", dual);
                #endregion
            }

            public static void Plane(Pt a, Pt b, Pt c, Quad plane, DP dual)
            {
                #region GMac : PlaneThroughPoints
                //GMac.Bind("p1", "NormalizedPoint3D", a);
                //GMac.Bind("p2", "NormalizedPoint3D", b);
                //GMac.Bind("p3", "NormalizedPoint3D", c);
                //GMac.Bind("plane", "Plane3D", plane);
                //GMac.Bind("dualPlane", "DualPlane3D", dual);
                #endregion
            }

            public static void Circle(Pt a, Pt b, Pt c, Tri circle, Bi dual)
            {
                #region GMac : CircleThroughPoints
                //GMac.Bind("p1", "NormalizedPoint3D", a);
                //GMac.Bind("p2", "NormalizedPoint3D", b);
                //GMac.Bind("p3", "NormalizedPoint3D", c);
                //GMac.Bind("phi", "Circle3D", circle);
                //GMac.Bind("dualCircle", "PointPair3D", dual);
                #endregion
            }

            public static void Line(Pt a, Pt b, Tri line, Bi dual)
            {
                #region GMac : LineThroughPoints
                //GMac.Bind("p1", "NormalizedPoint3D", a);
                //GMac.Bind("p2", "NormalizedPoint3D", b);
                //GMac.Bind("line", "Line3D", line);
                //GMac.Bind("dualLine", "DualLine3D", dual);
                #endregion
            }

            public static void Pair(Pt a, Pt b, Bi pair, Tri dual)
            {
                #region GMac : PointPair
                //GMac.Bind("p1", "NormalizedPoint3D", a);
                //GMac.Bind("p2", "NormalizedPoint3D", b);
                //GMac.Bind("pair", "PointPair3D", pair);
                //GMac.Bind("dualPair", "Circle3D", dual);
                #endregion
            }

            public static void Rotation(P3 axis, double angle, Ver v, Rot r)
            {
                #region GMac : RotationVersor
                //GMac.Bind("axis.e1", "<axis.x>");
                //GMac.Bind("axis.e2", "<axis.y>");
                //GMac.Bind("axis.e3", "<axis.z>");
                //GMac.Bind("angle.1", angle);
                //GMac.Bind("v", "Versor3D", v);
                #endregion
            }
        }
        """;

    [Fact]
    public void Regions_that_bind_only_inputs_declare_default_outputs_build_and_verify()
    {
        var types = _temp.Write("Types.cs", Types);
        var path = _temp.Write("InputsOnly.cs", InputsOnly);
        var (exit, _, err) = Tool.Generate([path]);
        Assert.True(exit == 0, err);
        var text = File.ReadAllText(path);
        foreach (var declared in new[] { "double d2_s = ", "double centre_e1 = ", "double y_e1 = ", "double q_ni = ", "double sigma_e1_e2_e3_ni = ", "double omega_no = " })
            Assert.Contains(declared, text);
        Assert.Empty(CSharpCompile.Errors(types, path));
        var (verified, output, verifyErr) = Tool.Verify(path);
        Assert.True(verified == 0, verifyErr + output);
        Assert.Contains("6 region(s), 6 passed, 0 problem(s)", output);
    }

    [Fact]
    public void Class_bindings_write_every_conformal_object_and_verify()
    {
        var types = _temp.Write("Types.cs", Types);
        var path = _temp.Write("Objects.cs", Outputs);
        var (exit, _, err) = Tool.Generate([path]);
        Assert.True(exit == 0, err);
        var text = File.ReadAllText(path);
        foreach (var written in new[] { "sphere.e1_e2_e3_ni = ", "dual.no = ", "plane.no_e1_e2_ni = ", "dual.ni = ", "circle.e1_e2_e3 = ", "dual.e1_e2 = ", "line.e1_e2_ni = ", "pair.no_ni = ", "v.s = ", "v.e1_e2 = " })
            Assert.Contains(written, text);
        Assert.Empty(CSharpCompile.Errors(types, path));
        var (verified, output, verifyErr) = Tool.Verify(path);
        Assert.True(verified == 0, verifyErr + output);
        Assert.Contains("6 region(s), 6 passed, 0 problem(s)", output);
    }

    [Theory]
    [InlineData("SquaredDistance", "double d2_s = ", "p=NormalizedPoint3D:a", "q=NormalizedPoint3D:b")]
    [InlineData("SphereCentreAndRadius", "double radius_s = Math.Sqrt(", "omega=DualSphere3D:s")]
    [InlineData("ApplyUnitRotor3D", "double y_e3 = ", "r=UnitRotor3D:q", "x=Vector3D:v")]
    [InlineData("ApplyVersorToPoint", "double q_e1 = ", "v=Versor3D:v", "p=NormalizedPoint3D:a")]
    [InlineData("CircleThroughPoints", "double dualCircle_no_ni = ", "p1=NormalizedPoint3D:a", "p2=NormalizedPoint3D:b", "p3=NormalizedPoint3D:c")]
    public void Show_with_only_inputs_bound_prints_declared_default_outputs(string macro, string expected, params string[] binds)
    {
        var (exit, output, err) = Tool.Run(["show", macro, "--dsl", Dsl, .. binds.SelectMany(b => new[] { "--bind", b })]);
        Assert.True(exit == 0, err);
        Assert.Contains(expected, output);
    }
}
