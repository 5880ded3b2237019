namespace RayTracer.Cli;

/// <summary>A command line that cannot be run; reported with the usage text and exit code 2.</summary>
public sealed class UsageException(string message) : Exception(message);
