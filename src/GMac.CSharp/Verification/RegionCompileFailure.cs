using GMac.CSharp.BindingPoints;
using GMac.Dsl.Diagnostics;

namespace GMac.CSharp.Verification;

/// <summary>A region whose code does not compile where it is written, with the first compiler error inside it.</summary>
internal sealed record RegionCompileFailure(GeneratedRegion Region, Diagnostic Diagnostic);
