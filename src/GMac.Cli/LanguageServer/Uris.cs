namespace GMac.Cli.LanguageServer;

/// <summary>Between <c>file://</c> URIs of the protocol and the full paths the DSL project reports.</summary>
internal static class Uris
{
    public static string FromPath(string path) => new Uri(Path.GetFullPath(path)).AbsoluteUri;

    public static string ToPath(string uri) =>
        Uri.TryCreate(uri, UriKind.Absolute, out var u) && u.IsFile ? Path.GetFullPath(u.LocalPath) : uri;
}
