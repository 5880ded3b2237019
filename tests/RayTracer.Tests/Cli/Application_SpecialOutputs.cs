using System.Net.Sockets;
using System.Runtime.InteropServices;
using RayTracer.Viewing.Imaging;
using SafeFiles;

namespace RayTracer.Tests.Cli;

/// <summary><c>render -o</c> naming something other than a regular file: written into (a FIFO) or refused, never replaced.</summary>
public sealed class Application_SpecialOutputs : CommandLineTest
{
    private static readonly string[] Small = ["--width", "8", "--height", "6", "--spp", "1", "--threads", "1"];

    [Fact]
    public async Task A_fifo_is_written_into_and_stays_a_fifo()
    {
        if (!OperatingSystem.IsLinux())
            return;
        var fifo = Path.Combine(Dir, "out.png");
        Assert.Equal(0, MakeFifo(fifo, Convert.ToUInt32("600", 8)));
        // Opening a FIFO to read waits for a writer, so the reader runs on its own thread.
        var reader = Task.Factory.StartNew(() => File.ReadAllBytes(fifo), TaskCreationOptions.LongRunning);

        var (code, _, err) = Run(["render", "spheres", "-o", fifo, .. Small]);

        Assert.True(code == 0, err);
        Assert.Equal(FileKind.Special, FileStat.KindOf(fifo));
        // The time limit is only a safety net against a reader left waiting for a writer that never came.
        var image = ImageFile.DecodePixels(await reader.WaitAsync(TimeSpan.FromSeconds(60)), fifo);
        Assert.Equal((8, 6), (image.Width, image.Height));
    }

    [Fact]
    public void A_link_to_a_socket_is_refused_and_left_as_it_is()
    {
        if (!OperatingSystem.IsLinux())
            return;
        // A socket stands for any special file that is not a FIFO, such as a device: it is as safe to lose in a test.
        var socketPath = Path.Combine(Dir, "service.sock");
        using var socket = new Socket(AddressFamily.Unix, SocketType.Stream, ProtocolType.Unspecified);
        socket.Bind(new UnixDomainSocketEndPoint(socketPath));
        var link = Path.Combine(Dir, "out.png");
        File.CreateSymbolicLink(link, socketPath);

        var (code, _, err) = Run(["render", "spheres", "-o", link, .. Small]);

        Assert.Equal(1, code);
        Assert.Contains($"cannot write '{link}'", err);
        Assert.Contains("is a socket (through a symbolic link), not a regular file", err);
        Assert.Equal(socketPath, new FileInfo(link).LinkTarget);
        Assert.Equal(FileKind.Special, FileStat.KindOf(socketPath));
        Assert.Equal(["out.png", "service.sock"], Directory.GetFileSystemEntries(Dir).Select(Path.GetFileName).Order());
    }

    [Fact]
    public void A_regular_file_is_still_replaced()
    {
        var output = Path.Combine(Dir, "out.png");
        File.WriteAllText(output, "old");

        Assert.Equal(0, Run(["render", "spheres", "-o", output, .. Small]).Code);

        Assert.Equal((8, 6), (ImageFile.ReadPixels(output).Width, ImageFile.ReadPixels(output).Height));
    }

    [DllImport("libc", EntryPoint = "mkfifo", SetLastError = true)]
    private static extern int MakeFifo([MarshalAs(UnmanagedType.LPUTF8Str)] string path, uint mode);
}
