using System.CommandLine;
using System.Globalization;

namespace RayTracer.Cli;

/// <summary>Option builders shared by the commands, with range checks whose messages name the option and the limits.</summary>
internal static class Options
{
    public const int MaxResolution = 16384, MaxThreads = 1024;

    /// <summary>An optional integer option that must lie in [<paramref name="min"/>, <paramref name="max"/>].</summary>
    public static Option<int?> Integer(string name, string description, int min, int max, params string[] aliases)
    {
        return new Option<int?>(name, aliases)
        {
            Description = $"{description}; {min} to {max}",
            HelpName = "N",
            // Parsing and the range check in one place, so both kinds of mistake read alike.
            CustomParser = result =>
            {
                var text = result.Tokens.Single().Value;
                if (!int.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out var value))
                    result.AddError($"{name} expects an integer, got '{text}'");
                else if (value < min || value > max)
                    result.AddError($"{name} must be between {min} and {max}, got {value}");
                else
                    return value;
                return null;
            },
        };
    }

    /// <summary>An optional path option whose file must exist and end in one of <paramref name="extensions"/> (any if empty).</summary>
    public static Option<string?> ExistingFile(string name, string description, params string[] extensions)
    {
        var option = new Option<string?>(name) { Description = description, HelpName = "FILE" };
        option.Validators.Add(result =>
        {
            if (result.GetValueOrDefault<string?>() is not { } path)
                return;
            var extension = Path.GetExtension(path).ToLowerInvariant();
            if (extensions.Length > 0 && !extensions.Contains(extension))
                result.AddError($"{name} '{path}' must end in {string.Join(" or ", extensions)}");
            else if (!File.Exists(path))
                result.AddError($"{name} '{path}': no such file");
        });
        return option;
    }
}
