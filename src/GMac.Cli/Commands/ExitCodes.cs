namespace GMac.Cli.Commands;

internal static class ExitCodes
{
    public const int Success = 0;
    public const int Diagnostics = 1;
    public const int Usage = 2;
}
