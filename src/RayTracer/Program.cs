namespace RayTracer;

internal static class Program
{
    private static int Main(string[] args)
    {
        Console.WriteLine("raytracer: under construction.");
        return 0;
    }
}
