using GMac.Core.Numerics;
using GMac.Dsl.Semantics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Library;

/// <summary>The shipped dsl/ library is clean and defines what the ray tracer and the thesis examples need.</summary>
public sealed class DslLibrary_Binds
{
    private static readonly Lazy<DslProject> Library = new(() => DslProject.Load(RepositoryPaths.DslLibrary));

    [Fact]
    public void Library_has_no_errors_or_warnings()
    {
        Assert.True(Library.Value.Diagnostics.Count == 0, string.Join("\n", Library.Value.Diagnostics));
    }

    [Theory]
    [InlineData("GetNormalToVectors")]
    [InlineData("SphereThroughPoints")]
    [InlineData("PlaneThroughPoints")]
    [InlineData("CircleThroughPoints")]
    [InlineData("LineThroughPoints")]
    [InlineData("PointPair")]
    [InlineData("TangentVector")]
    [InlineData("TangentBivector")]
    [InlineData("TranslationVersor")]
    [InlineData("RotationVersor")]
    [InlineData("ScalingVersor")]
    [InlineData("GeneralRotationVersor")]
    [InlineData("TwistVersor")]
    [InlineData("ApplyTwistToPoint3D")]
    [InlineData("CircleCurveTangent")]
    [InlineData("SphereSurfaceNormal")]
    [InlineData("PluckerRayTriangle")]
    [InlineData("HiddenSurface")]
    [InlineData("VortexS")]
    [InlineData("Circ3")]
    [InlineData("GramSchmidtContraction")]
    [InlineData("GramSchmidtRejection")]
    [InlineData("RotorToMatrix")]
    [InlineData("JuliaStep3")]
    [InlineData("JuliaStep5")]
    [InlineData("RotorInterpolate")]
    [InlineData("SkewLinesClosestPoints")]
    public void Thesis_macro_is_defined_with_statements(string name)
    {
        var macro = Library.Value.Model.Macros[name];
        Assert.NotEmpty(macro.Statements);
        Assert.NotEmpty(macro.Outputs);
    }

    [Fact]
    public void Conformal_frame_has_the_null_basis_of_equation_3_68()
    {
        var cga = Library.Value.Model.Frames["cga5d"];
        Assert.Equal(["no", "e1", "e2", "e3", "ni"], cga.BasisNames);
        Assert.Equal(Rational.MinusOne, cga.InnerProductMatrix[0, 4]);
        Assert.Equal(Rational.Zero, cga.InnerProductMatrix[0, 0]);
        Assert.Equal(Rational.Zero, cga.InnerProductMatrix[4, 4]);
    }

    [Fact]
    public void Orthogonal_companion_is_e_and_ebar_of_equation_3_68()
    {
        var orth = Library.Value.Model.Frames["cga5dOrth"];
        Assert.Equal(FrameKind.Orthogonalized, orth.Kind);
        var half = new Rational(1, 2);
        // Diagonal (1, 1, 1, 1, −1); rows of the BCM in (no, e1, e2, e3, ni).
        Assert.Equal([1, 1, 1, 1, -1], Enumerable.Range(0, 5).Select(i => (int)orth.InnerProductMatrix[i, i].Numerator));
        Assert.Equal([Rational.One, 0, 0, 0, -half], Row(orth.BasisChangeMatrix!, 3)); // e = no − ni/2
        Assert.Equal([Rational.One, 0, 0, 0, half], Row(orth.BasisChangeMatrix!, 4));  // ebar = no + ni/2
    }

    [Fact]
    public void Ray_tracer_bindings_read_x_y_z()
    {
        foreach (var name in new[] { "Point3D", "Vector3D", "Normal3D" })
        {
            var binding = Library.Value.Model.ClassBindings[name];
            Assert.Equal("e3d", binding.Frame.Name);
            var members = binding.Coefficients.Select(c => ((BoundMemberReference)c.Value).Path).ToList();
            Assert.Equal(["x", "y", "z"], members);
        }
    }

    [Fact]
    public void Unit_rotor_class_is_normalized()
    {
        Assert.True(Library.Value.Model.FindClass("e3d.UnitRotor")!.IsNormalized);
        Assert.Equal(nameof(BoundUnaryOperation), Library.Value.Model.Macros["RotorToMatrix"].Statements
            .OfType<BoundAssignment>().First().Value.GetType().Name);
    }

    private static Rational[] Row(RationalMatrix m, int i) => Enumerable.Range(0, m.Columns).Select(j => m[i, j]).ToArray();
}
