using System.Reflection;
using static GMac.Dsl.Diagnostics.DiagnosticSeverity;

namespace GMac.Dsl.Diagnostics;

/// <summary>
/// Every diagnostic code gmac reports, each defined here once and in increasing order:
/// 00xx reading the DSL, 01xx its meaning, 02xx DSL warnings, 03xx generating a binding point,
/// 04xx binding points, C# files and verification. docs/diagnostics.md lists the same table.
/// </summary>
public static class DiagnosticCodes
{
    // ---- reading the DSL
    public static readonly DiagnosticDescriptor SyntaxError = new("GMAC0001", Error, "the text is not valid GMacDSL", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor NestingTooDeep = new("GMAC0002", Error, "an expression is nested too deeply to read", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor CannotReadDsl = new("GMAC0003", Error, "the DSL folder or one of its files cannot be read, or it holds no .gmac file", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor FileTooLarge = new("GMAC0004", Error, "a DSL file has more tokens than gmac reads from one file", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor CookbookAnnotation = new("GMAC0005", Error, "a cookbook annotation of the DSL is malformed, names what the DSL does not define, or shows a binding point that does not generate", ReportedBy.Cookbook);

    // ---- names
    public static readonly DiagnosticDescriptor UnknownName = new("GMAC0101", Error, "a name is not defined (a close match is suggested)", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor Duplicate = new("GMAC0102", Error, "a name is defined twice", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor WrongKind = new("GMAC0103", Error, "a name is used as a different kind of thing than it is", ReportedBy.DslLoad);

    // ---- macros
    public static readonly DiagnosticDescriptor FrameMismatch = new("GMAC0110", Error, "the operands of an operation belong to different frames", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor AssignToInput = new("GMAC0111", Error, "a macro assigns to one of its inputs", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor OutputReadBeforeAssignment = new("GMAC0112", Error, "a macro reads an output before assigning it", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor OutputClassMismatch = new("GMAC0113", Error, "the value assigned to an output does not fit the output's class", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor CyclicCall = new("GMAC0114", Error, "macro calls form a cycle", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor UsedBeforeAssignment = new("GMAC0115", Error, "a variable is used before it is assigned", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor TypeError = new("GMAC0116", Error, "an operation, function or blade does not fit its operands", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor CallError = new("GMAC0117", Error, "a macro call does not match the macro's inputs and outputs", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor NoDual = new("GMAC0118", Error, "dual or undual in a frame whose metric is not invertible (degenerate); rcomplement, lcomplement and vee work there", ReportedBy.DslLoad);

    // ---- frames, transforms, matrices
    public static readonly DiagnosticDescriptor NotInvertible = new("GMAC0120", Error, "'inverse of' names a transform that is not invertible", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor MatrixSize = new("GMAC0121", Error, "a matrix has the wrong number of rows or columns", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor NonSymmetricIpm = new("GMAC0122", Error, "an inner product matrix is not symmetric", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor DefinitionCycle = new("GMAC0123", Error, "frame or transform definitions form a cycle", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor InvalidDefinition = new("GMAC0124", Error, "a frame or transform definition is invalid (size, signature, singular matrix)", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor EmptyLimits = new("GMAC0125", Error, "a class binding's minimum and maximum of a member leave no value", ReportedBy.DslLoad);

    // ---- scalar expressions
    public static readonly DiagnosticDescriptor InvalidScalar = new("GMAC0130", Error, "a scalar expression is invalid where it is written", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor ConstantDivisionByZero = new("GMAC0131", Error, "a constant expression divides by zero", ReportedBy.DslLoad);
    public static readonly DiagnosticDescriptor NoRealValue = new("GMAC0132", Error, "a constant expression has no finite real value", ReportedBy.DslLoad);

    // ---- output blocks
    public static readonly DiagnosticDescriptor InvalidOutputText = new("GMAC0140", Error, "the text of an output block is not C# statements that can go into a region (a directive, an unclosed comment or string)", ReportedBy.DslLoad);

    // ---- operations
    public static readonly DiagnosticDescriptor GeneralInverseTooLarge = new("GMAC0155", Error, "general_inverse in a frame of more than 5 dimensions, where it has no closed form", ReportedBy.DslLoad);

    // ---- DSL warnings
    public static readonly DiagnosticDescriptor Unused = new("GMAC0201", Warning, "a subspace, constant, transform or temporary is never used", ReportedBy.Check);
    public static readonly DiagnosticDescriptor OutputNeverAssigned = new("GMAC0202", Warning, "a macro never assigns one of its outputs", ReportedBy.Check);
    public static readonly DiagnosticDescriptor SkippedDslFile = new("GMAC0203", Warning, "a special file in the DSL folder (device, pipe, socket) is skipped", ReportedBy.Check);
    public static readonly DiagnosticDescriptor SignatureOrder = new("GMAC0204", Warning, "signature (p, q, r) makes a basis vector named like the usual null or negative one positive, and another null or negative", ReportedBy.Check);

    // ---- generating a binding point
    public static readonly DiagnosticDescriptor UnknownMacro = new("GMAC0301", Error, "a binding point names a macro the DSL does not define", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor UnknownParameter = new("GMAC0302", Error, "a binding names no input or output of the macro", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor UnknownBlade = new("GMAC0303", Error, "a binding names a blade its frame does not have", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor NotACoefficient = new("GMAC0304", Error, "a binding names a coefficient that the parameter's class does not leave free", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor BoundTwice = new("GMAC0305", Error, "a coefficient is bound twice", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor UnusedAssumption = new("GMAC0306", Error, "an AssumeMin or AssumeMax names an expression no binding reads", ReportedBy.Generation);
    // GMAC0307 (no output bound) is retired: a binding point that binds only inputs gets default output names.
    public static readonly DiagnosticDescriptor InvalidBindingValue = new("GMAC0308", Error, "a bound value is neither a number, a C# expression in angle brackets, nor a scalar expression of these", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor ClassBindingMismatch = new("GMAC0309", Error, "a class binding is unknown or on another frame than the parameter", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor CannotGenerate = new("GMAC0310", Error, "the macro cannot be evaluated for these bindings", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor OutputNotATarget = new("GMAC0311", Error, "an output is bound to an expression rather than a target it can be written to", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor EmptyAssumption = new("GMAC0312", Error, "assumed minimum and maximum of one expression leave no value", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor GeneratedDivisionByZero = new("GMAC0313", Error, "the macro divides by an expression that is zero for these bindings", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor TooLarge = new("GMAC0314", Error, "an operation of the macro is too large to evaluate symbolically", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor ConstantOutOfRange = new("GMAC0315", Error, "a constant of the generated code is outside the range of its scalar type (float or double, also as the lanes of a vector type)", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor UnboundInput = new("GMAC0317", Error, "an input is bound by no line, or a coefficient is left out of a grade whose others are bound (write \"0\" to mean zero)", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor OutsideDomain = new("GMAC0320", Error, "exp, log or sqrt of a multivector outside the forms they are defined for (exp: bivectors up to 5D; log and sqrt: rotors and motors whose planes square to ≤ 0)", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor GeneratedNotInvertible = new("GMAC0325", Error, "the macro inverts a multivector that has no inverse for these bindings (a null versor or blade, or A adj(A) = 0)", ReportedBy.Generation);

    // ---- binding points, C# files, verification
    public static readonly DiagnosticDescriptor UnmatchedEndRegion = new("GMAC0401", Error, "#endregion without a matching #region", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor UnmatchedRegion = new("GMAC0402", Error, "#region without a matching #endregion", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor NestedRegion = new("GMAC0403", Error, "a region is nested inside a GMac region", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor InvalidBindingLine = new("GMAC0404", Error, "a //GMac. line cannot be read", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor TargetNotAssignable = new("GMAC0405", Error, "the C# target of an output cannot be assigned", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor CannotWrite = new("GMAC0406", Error, "the generated code cannot be written, or the file changed during the run; it is left as it is", ReportedBy.Generate | ReportedBy.Build);
    public static readonly DiagnosticDescriptor CannotReadSource = new("GMAC0407", Error, "a path does not exist or a C# file cannot be read", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor InvalidMacroName = new("GMAC0408", Error, "'#region GMac :' is not followed by a macro name", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor InternalError = new("GMAC0409", Error, "a defect of gmac while generating or printing one binding point", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor OutOfDate = new("GMAC0410", Error, "with --check: a binding point differs from what gmac generates", ReportedBy.Generate);
    public static readonly DiagnosticDescriptor SkippedSourceFile = new("GMAC0411", Warning, "a special file (device, pipe, socket) or a named file that is not a .cs file is skipped", ReportedBy.Generate | ReportedBy.Build);
    public static readonly DiagnosticDescriptor NotAnExpression = new("GMAC0412", Error, "the C# text of a binding is not exactly one C# expression", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor InvalidScalarType = new("GMAC0413", Error, "a GMac.Type line names a scalar type gmac does not write (float, double, Vector128/256/512 or Vector of float or double), or is given twice", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor TargetHasEffects = new("GMAC0419", Error, "the C# target of an output calls, assigns or increments, so it would run at every write", ReportedBy.Generation);
    public static readonly DiagnosticDescriptor DisagreesWithEngine = new("GMAC0420", Error, "the generated code disagrees with the numeric engine", ReportedBy.Verify);
    public static readonly DiagnosticDescriptor KernelDoesNotCompile = new("GMAC0421", Error, "the generated code does not compile on its own", ReportedBy.Verify);
    public static readonly DiagnosticDescriptor DoesNotCompileInProject = new("GMAC0422", Error, "the generated code does not compile in its file and project", ReportedBy.Verify);
    public static readonly DiagnosticDescriptor DirectiveInRegion = new("GMAC0430", Error, "a preprocessor directive (#pragma, #nullable, #if…) inside a GMac region, where it would be deleted", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor RegionNotAmongStatements = new("GMAC0431", Error, "a GMac region is where statements cannot stand (among members, in an expression, under an if without braces)", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor AlreadyDeclared = new("GMAC0432", Error, "the code of a region declares a local already declared where it goes (a default output name, by a parameter or another region)", ReportedBy.Generate | ReportedBy.Verify | ReportedBy.Build);
    public static readonly DiagnosticDescriptor InvalidBatch = new("GMAC0440", Error, "a batch binding point reads or writes what is not one item of its spans: the index other than as span[i], an output not written at [i], no span at all, or a second Batch line", ReportedBy.SourceFiles);
    public static readonly DiagnosticDescriptor InvalidFusedMultiplyAdd = new("GMAC0455", Error, "a GMac.Fma line whose argument is not true or false, or a second GMac.Fma line", ReportedBy.SourceFiles);

    /// <summary>Every descriptor above, in the order written.</summary>
    public static IReadOnlyList<DiagnosticDescriptor> All { get; } = typeof(DiagnosticCodes)
        .GetFields(BindingFlags.Public | BindingFlags.Static)
        .Where(f => f.FieldType == typeof(DiagnosticDescriptor))
        .OrderBy(f => f.MetadataToken)
        .Select(f => (DiagnosticDescriptor)f.GetValue(null)!)
        .ToList();
}
