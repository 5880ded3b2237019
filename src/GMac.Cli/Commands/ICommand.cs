namespace GMac.Cli.Commands;

/// <summary>One <c>gmac</c> sub-command.</summary>
internal interface ICommand
{
    string Name { get; }
    string Summary { get; }
    string Usage { get; }

    /// <summary>Runs with the arguments after the command name; returns the exit code.</summary>
    int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error);
}
