namespace GMac.CSharp.Tests.Support;

/// <summary>
/// Tests that use <see cref="SharedDsl"/> run one at a time: the code generator behind it is
/// loaded once and is not meant to be used from several threads at once.
/// </summary>
[CollectionDefinition(Name)]
public sealed class SharedDslCollection
{
    public const string Name = "shared DSL";
}
