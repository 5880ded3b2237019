using System.Globalization;

namespace RayTracer.Cli;

/// <summary>
/// Splits arguments into positionals and <c>--name value</c> options (also <c>--name=value</c> and
/// <c>-o value</c>), rejecting unknown or repeated options.
/// </summary>
public sealed class OptionReader
{
    private readonly Dictionary<string, string> _options = new(StringComparer.Ordinal);

    public OptionReader(IEnumerable<string> args, IReadOnlyDictionary<string, string> aliases, IReadOnlySet<string> known)
    {
        using var e = args.GetEnumerator();
        while (e.MoveNext())
        {
            var arg = e.Current;
            if (!arg.StartsWith('-') || arg == "-")
            {
                Positionals.Add(arg);
                continue;
            }
            string name, value;
            var eq = arg.IndexOf('=');
            if (eq > 0)
            {
                name = arg[..eq];
                value = arg[(eq + 1)..];
            }
            else
            {
                name = arg;
                if (!e.MoveNext())
                    throw new UsageException($"option {arg} needs a value");
                value = e.Current;
            }
            if (aliases.TryGetValue(name, out var canonical))
                name = canonical;
            if (!known.Contains(name))
                throw new UsageException($"unknown option {name}");
            if (!_options.TryAdd(name, value))
                throw new UsageException($"option {name} given more than once");
        }
    }

    public List<string> Positionals { get; } = [];

    public string? GetString(string name) => _options.GetValueOrDefault(name);

    public int? GetInt(string name, int min, int max)
    {
        if (!_options.TryGetValue(name, out var text))
            return null;
        if (!int.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out var value))
            throw new UsageException($"{name} expects an integer, got '{text}'");
        if (value < min || value > max)
            throw new UsageException($"{name} must be between {min} and {max}, got {value}");
        return value;
    }

    public ulong? GetULong(string name)
    {
        if (!_options.TryGetValue(name, out var text))
            return null;
        if (!ulong.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out var value))
            throw new UsageException($"{name} expects a non-negative integer, got '{text}'");
        return value;
    }
}
