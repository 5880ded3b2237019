namespace GMac.Cli;

internal static class Program
{
    private static int Main(string[] args)
    {
        Console.WriteLine("gmac: commands arrive with the code generator.");
        return 0;
    }
}
