using System.Diagnostics;
using System.Globalization;

namespace RayTracer.Cli;

/// <summary>
/// Progress bar with percentage and remaining-time estimate on a text writer (stderr). On a terminal it
/// redraws one line; when redirected it prints a line every 10 %. Safe to call from several threads.
/// </summary>
public sealed class ProgressBar(TextWriter output, bool interactive, int width = 30)
{
    private readonly Lock _gate = new();
    private readonly Stopwatch _clock = Stopwatch.StartNew();
    private int _lastShown = -1;

    public static string FormatDuration(TimeSpan t) =>
        t.TotalHours >= 1 ? t.ToString(@"h\:mm\:ss", CultureInfo.InvariantCulture) : t.ToString(@"mm\:ss", CultureInfo.InvariantCulture);

    /// <summary>The bar text for <paramref name="done"/> of <paramref name="total"/> after <paramref name="elapsed"/>.</summary>
    public static string Render(int done, int total, TimeSpan elapsed, int width)
    {
        var fraction = total == 0 ? 1.0 : (double)done / total;
        var filled = (int)Math.Round(fraction * width);
        var eta = done == 0 ? "--:--" : FormatDuration(TimeSpan.FromSeconds(elapsed.TotalSeconds * (total - done) / done));
        return string.Create(CultureInfo.InvariantCulture,
            $"[{new string('#', filled)}{new string('.', width - filled)}] {fraction * 100,3:F0}%  {done}/{total} tiles  elapsed {FormatDuration(elapsed)}  ETA {eta}");
    }

    public void Report(int done, int total)
    {
        lock (_gate)
        {
            var percent = total == 0 ? 100 : done * 100 / total;
            var step = interactive ? percent : percent / 10 * 10;
            if (step == _lastShown && done != total)
                return;
            _lastShown = step;
            var line = Render(done, total, _clock.Elapsed, width);
            if (interactive)
                output.Write("\r" + line + (done == total ? Environment.NewLine : ""));
            else
                output.WriteLine(line);
            output.Flush();
        }
    }
}
