namespace GMac.Core.CodeGeneration;

/// <summary>The optimized code block of one binding point and how it was chosen.</summary>
public sealed record CodeGenerationResult(CodeBlock Block, CodeStatistics Statistics, JoinMode Form, CodeStatistics? Alternative);
