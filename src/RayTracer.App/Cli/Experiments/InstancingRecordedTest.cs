using RayTracer.Tracing;

namespace RayTracer.Cli.Experiments;

/// <summary>One test asked of a tube during the counting render, kept to be asked again, timed.</summary>
internal readonly record struct InstancingRecordedTest(int Tube, InstancingTestKind Kind, Ray Ray, double MaxDistance);
