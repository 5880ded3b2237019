using GMac.CSharp.BindingPoints;
using GMac.Dsl.Generation;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary><c>//GMac.Type("float");</c>: read as a scalar type spec with its position; other forms are refused.</summary>
public sealed class BindingLineReader_TypeLines
{
    [Fact]
    public void A_type_line_keeps_the_name_as_written_with_its_position()
    {
        var read = BindingLineReader.Read("        //GMac.Type(\"float\"); // graphics code\n", 12);
        var spec = Assert.IsType<ScalarTypeSpec>(read!.Spec);
        Assert.Equal(("float", 12, 9), (spec.TypeName, spec.Line, spec.Column));
        // The name is checked where code is emitted, so a wrong one still reads (and is reported there).
        Assert.Equal("Single", Assert.IsType<ScalarTypeSpec>(BindingLineReader.Read("//GMac.Type(\"Single\");", 1)!.Spec).TypeName);
    }

    [Theory]
    [InlineData("//GMac.Type();")]
    [InlineData("//GMac.Type(\"float\", \"double\");")]
    [InlineData("//GMac.Type(single);")]
    public void A_type_line_without_exactly_one_string_is_refused(string line)
    {
        var read = BindingLineReader.Read(line, 1)!;
        Assert.False(read.Succeeded);
        Assert.Contains("GMac.Type takes one string", read.Error);
    }
}
