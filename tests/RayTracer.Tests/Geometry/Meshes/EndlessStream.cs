namespace RayTracer.Tests.Geometry.Meshes;

/// <summary>
/// A pipe that gives <paramref name="start"/> and then zero bytes without end, like a link to /dev/zero.
/// Past <paramref name="limit"/> bytes it throws, so a reader that tries to take it whole fails instead of
/// exhausting memory.
/// </summary>
internal sealed class EndlessStream(byte[] start, long limit) : Stream
{
    public long BytesRead { get; private set; }

    public override bool CanRead => true;

    public override bool CanSeek => false;

    public override bool CanWrite => false;

    public override long Length => throw new NotSupportedException();

    public override long Position
    {
        get => throw new NotSupportedException();
        set => throw new NotSupportedException();
    }

    public override int Read(byte[] buffer, int offset, int count)
    {
        if (BytesRead >= limit)
        {
            throw new InvalidOperationException($"read more than {limit} bytes of an endless stream");
        }

        for (int i = 0; i < count; i++)
        {
            buffer[offset + i] = BytesRead + i < start.Length ? start[BytesRead + i] : (byte)0;
        }

        BytesRead += count;
        return count;
    }

    public override void Flush()
    {
    }

    public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

    public override void SetLength(long value) => throw new NotSupportedException();

    public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
}
