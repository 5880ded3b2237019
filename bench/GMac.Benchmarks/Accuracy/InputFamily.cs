namespace GMac.Benchmarks.Accuracy;

/// <summary>A kind of input a kernel is tested on: random, far from the origin, nearly degenerate, …</summary>
/// <param name="Create">One input, boxed as the kernel's input type.</param>
public sealed record InputFamily(string Name, string Description, Func<Random, object> Create);
