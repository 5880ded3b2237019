using RayTracer.Cli;

namespace RayTracer;

internal static class Program
{
    private static int Main(string[] args) =>
        Application.Run(args, Console.Out, Console.Error, interactiveProgress: !Console.IsErrorRedirected);
}
