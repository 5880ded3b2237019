namespace GMac.Core.CodeGeneration.Passes;

/// <summary>One rewrite of a code block that keeps every output's value.</summary>
public interface IOptimizerPass
{
    string Name { get; }

    CodeBlock Run(CodeBlock block);
}
