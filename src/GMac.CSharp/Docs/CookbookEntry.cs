using GMac.Core.CodeGeneration;
using GMac.Dsl.Semantics;

namespace GMac.CSharp.Docs;

/// <summary>One macro of the cookbook: its group, the binding point a user writes for it, and what that generates.</summary>
internal sealed record CookbookEntry(MacroSymbol Macro, string Description, string BindingPoint, CodeStatistics Statistics, string? Hand);
