using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using RayTracer.Maths;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Reads STL files (ASCII and binary) into an indexed mesh. STL stores every triangle with its own
/// corners, so identical corner positions are merged into shared vertices (needed for smooth
/// normals). Facet normals in the file are ignored; the winding defines the orientation.
/// The file is streamed, never held whole: memory grows with the triangles actually read, and a binary
/// file is read no further than the triangles its header declares. A file whose size is exactly
/// 84 + 50 n for the n in its header is binary; otherwise its first bytes decide: text is ASCII STL,
/// anything with control bytes (as in every binary count or float) is binary.
/// </summary>
public static class StlReader
{
    /// <summary>How much of the start is looked at to tell text from binary.</summary>
    private const int SniffBytes = 512;

    private const int HeaderBytes = 84;
    private const int TriangleBytes = 50;

    public static Mesh Read(string path)
    {
        using var stream = File.OpenRead(path);
        return Read(stream, Path.GetFileName(path));
    }

    public static Mesh Read(Stream stream, string fileName)
    {
        ArgumentNullException.ThrowIfNull(stream);
        long? declaredLength = DeclaredLength(stream);
        var input = new StlInput(stream);
        var start = input.Peek(SniffBytes);
        if (start.Length == 0)
        {
            throw new MeshFormatException(fileName, "the file is empty; an STL file starts with 'solid' (ASCII) or an 84-byte header (binary)", 1, column: 1);
        }

        // A device such as /dev/zero may claim to seek and have length 0: trust a length only if the data fits in it.
        long? length = declaredLength >= input.Buffered ? declaredLength : null;
        uint? declared = start.Length >= HeaderBytes ? BinaryPrimitives.ReadUInt32LittleEndian(start[80..]) : null;
        if (declared is { } count && length == HeaderBytes + (long)TriangleBytes * count)
        {
            return ReadBinary(input, count, fileName);
        }

        if (IsText(start))
        {
            return ReadAscii(input, fileName);
        }

        if (declared is not { } claimed)
        {
            throw new MeshFormatException(
                fileName, $"not ASCII STL (it holds binary bytes) and, at {start.Length} bytes, too short for the 84-byte header of a binary STL", null, start.Length);
        }

        long expected = HeaderBytes + (long)TriangleBytes * claimed;
        if (length is { } size)
        {
            // Known size that does not match: refuse before reading a byte of it.
            string solid = StartsWithSolid(start) ? " (its header starts with 'solid', but the data after it is binary, not text)" : "";
            throw new MeshFormatException(
                fileName,
                size < expected
                    ? $"binary STL declares {claimed} triangles ({expected} bytes) but the file ends inside triangle {(size - HeaderBytes) / TriangleBytes}{solid}"
                    : $"binary STL declares {claimed} triangles ({expected} bytes) but the file has {size} bytes{solid}",
                null,
                Math.Min(size, expected));
        }

        return ReadBinary(input, claimed, fileName);
    }

    private static long? DeclaredLength(Stream stream)
    {
        try
        {
            return stream.CanSeek ? stream.Length - stream.Position : null;
        }
        catch (Exception e) when (e is IOException or NotSupportedException)
        {
            return null;
        }
    }

    /// <summary>
    /// Whether the bytes can be text: no control byte but white space. Binary STL always has some, in the
    /// triangle count or the floats; ASCII STL has none (UTF-8 in a solid's name is fine).
    /// </summary>
    private static bool IsText(ReadOnlySpan<byte> bytes)
    {
        foreach (byte b in bytes)
        {
            if ((b < 0x20 && b is not ((byte)'\t' or (byte)'\n' or (byte)'\r' or 0x0B or 0x0C)) || b == 0x7F)
            {
                return false;
            }
        }

        return true;
    }

    private static bool StartsWithSolid(ReadOnlySpan<byte> bytes) => bytes.TrimStart(" \t\r\n"u8).StartsWith("solid"u8);

    private static Mesh ReadBinary(StlInput input, uint count, string fileName)
    {
        var builder = new VertexMerger(count);
        input.Skip(HeaderBytes);
        Span<byte> triangle = stackalloc byte[TriangleBytes];
        for (long f = 0; f < count; f++)
        {
            long at = input.Offset;
            int read = input.Read(triangle);
            if (read < TriangleBytes)
            {
                throw new MeshFormatException(
                    fileName, $"binary STL declares {count} triangles ({HeaderBytes + (long)TriangleBytes * count} bytes) but the file ends inside triangle {f}", null, at + read);
            }

            for (int k = 0; k < 3; k++)
            {
                var s = triangle.Slice(12 + 12 * k, 12);
                for (int c = 0; c < 3; c++)
                {
                    float value = BinaryPrimitives.ReadSingleLittleEndian(s[(4 * c)..]);
                    if (!float.IsFinite(value))
                    {
                        throw new MeshFormatException(
                            fileName, $"triangle {f} vertex {k} has a non-finite {"xyz"[c]} ({value.ToString(CultureInfo.InvariantCulture)})", null, at + 12 + 12 * k + 4 * c);
                    }
                }

                builder.Add(new Point3D(
                    BinaryPrimitives.ReadSingleLittleEndian(s),
                    BinaryPrimitives.ReadSingleLittleEndian(s[4..]),
                    BinaryPrimitives.ReadSingleLittleEndian(s[8..])));
            }
        }

        // Whatever follows the declared triangles is not read: one byte tells that something does.
        if (input.Read(triangle[..1]) > 0)
        {
            long expected = HeaderBytes + (long)TriangleBytes * count;
            throw new MeshFormatException(
                fileName, $"binary STL declares {count} triangles ({expected} bytes) but the file goes on after them", null, expected);
        }

        return builder.ToMesh();
    }

    private static Mesh ReadAscii(StlInput input, string fileName)
    {
        // Editors on Windows may start the text with a UTF-8 byte-order mark.
        if (input.Peek(3).SequenceEqual("\uFEFF"u8))
        {
            input.Skip(3);
        }

        var tokens = new AsciiTokens(input, fileName);
        var builder = new VertexMerger(0);
        string first = tokens.Next("'solid'");
        if (first != "solid")
        {
            throw tokens.Error($"an ASCII STL file starts with 'solid', found '{first}' (and the file is text, so it is not binary STL)");
        }

        tokens.SkipRestOfLine();
        long facet = 0;
        while (true)
        {
            string word = tokens.Next("'facet' or 'endsolid'");
            if (word == "endsolid")
            {
                tokens.SkipRestOfLine();
                if (!tokens.AtEnd && tokens.Peek() == "solid")
                {
                    tokens.Next("solid");
                    tokens.SkipRestOfLine();
                    continue;
                }

                break;
            }

            if (word != "facet")
            {
                throw tokens.Error($"expected 'facet' or 'endsolid', found '{word}'");
            }

            tokens.Expect("normal");
            tokens.Number();
            tokens.Number();
            tokens.Number();
            tokens.Expect("outer");
            tokens.Expect("loop");
            var corners = new List<Point3D>(3);
            while (tokens.Peek() == "vertex")
            {
                tokens.Next("vertex");
                string where = $"facet {facet} vertex {corners.Count}";
                corners.Add(new Point3D(tokens.Coordinate(where, 'x'), tokens.Coordinate(where, 'y'), tokens.Coordinate(where, 'z')));
            }

            if (corners.Count < 3)
            {
                throw tokens.Error($"a facet needs at least 3 vertices, found {corners.Count}");
            }

            tokens.Expect("endloop");
            tokens.Expect("endfacet");
            facet++;
            for (int k = 2; k < corners.Count; k++)
            {
                builder.Add(corners[0]);
                builder.Add(corners[k - 1]);
                builder.Add(corners[k]);
            }
        }

        return builder.ToMesh();
    }

    private sealed class VertexMerger(uint declaredTriangles)
    {
        // A header's count may lie; reserve no more than a modest start and grow with the data.
        private readonly Dictionary<Point3D, int> _index = new((int)Math.Min(declaredTriangles, 1u << 14));
        private readonly List<Point3D> _vertices = new((int)Math.Min(declaredTriangles, 1u << 14));
        private readonly List<int> _indices = new((int)Math.Min(3L * declaredTriangles, 3 << 14));

        public void Add(Point3D p)
        {
            if (!_index.TryGetValue(p, out int i))
            {
                i = _vertices.Count;
                _vertices.Add(p);
                _index.Add(p, i);
            }

            _indices.Add(i);
        }

        public Mesh ToMesh() => new([.. _vertices], [.. _indices]);
    }

    /// <summary>A forward-only byte reader over a buffer, which can look ahead without consuming.</summary>
    private sealed class StlInput(Stream stream)
    {
        private readonly byte[] _buffer = new byte[1 << 16];
        private int _start;
        private int _end;

        /// <summary>Bytes consumed from the start of the file.</summary>
        public long Offset { get; private set; }

        /// <summary>Bytes read from the stream but not yet consumed.</summary>
        public int Buffered => _end - _start;

        /// <summary>Up to <paramref name="count"/> next bytes, fewer only at the end of the file; nothing is consumed.</summary>
        public ReadOnlySpan<byte> Peek(int count)
        {
            while (Buffered < count && Fill())
            {
            }

            return _buffer.AsSpan(_start, Math.Min(count, Buffered));
        }

        public int ReadByte()
        {
            if (_start == _end && !Fill())
            {
                return -1;
            }

            Offset++;
            return _buffer[_start++];
        }

        public int Read(Span<byte> destination)
        {
            int done = 0;
            while (done < destination.Length)
            {
                if (_start == _end && !Fill())
                {
                    break;
                }

                int n = Math.Min(destination.Length - done, _end - _start);
                _buffer.AsSpan(_start, n).CopyTo(destination[done..]);
                _start += n;
                done += n;
            }

            Offset += done;
            return done;
        }

        public void Skip(int count)
        {
            Span<byte> sink = stackalloc byte[count];
            Read(sink);
        }

        private bool Fill()
        {
            if (_start > 0)
            {
                _buffer.AsSpan(_start, _end - _start).CopyTo(_buffer);
                _end -= _start;
                _start = 0;
            }

            if (_end == _buffer.Length)
            {
                return false;
            }

            int read = stream.Read(_buffer, _end, _buffer.Length - _end);
            _end += read;
            return read > 0;
        }
    }

    /// <summary>Whitespace-separated words with their line and column for messages.</summary>
    private sealed class AsciiTokens(StlInput input, string fileName)
    {
        /// <summary>No STL keyword or number is near this long; a longer word is not STL and is not buffered whole.</summary>
        private const int MaxWordLength = 256;

        private readonly byte[] _bytes = new byte[MaxWordLength];
        private int _line = 1;
        private int _column = 1;
        private int _tokenLine = 1;
        private int _tokenColumn = 1;
        private (string Word, int Line, int Column)? _peeked;

        public bool AtEnd => _peeked is null && !SkipSpace();

        public MeshFormatException Error(string problem) => new(fileName, problem, _tokenLine, column: _tokenColumn);

        public string? Peek()
        {
            if (_peeked is { } peeked)
            {
                return peeked.Word;
            }

            if (AtEnd)
            {
                return null;
            }

            int line = _tokenLine, column = _tokenColumn;
            string word = Next("a word");
            _peeked = (word, _tokenLine, _tokenColumn);
            _tokenLine = line;
            _tokenColumn = column;
            return word;
        }

        public string Next(string expected)
        {
            if (_peeked is { } peeked)
            {
                _peeked = null;
                (_tokenLine, _tokenColumn) = (peeked.Line, peeked.Column);
                return peeked.Word;
            }

            bool more = SkipSpace();
            _tokenLine = _line;
            _tokenColumn = _column;
            if (!more)
            {
                throw new MeshFormatException(fileName, $"unexpected end of file, expected {expected}", _line, column: _column);
            }

            int length = 0;
            while (true)
            {
                var next = input.Peek(1);
                if (next.Length == 0 || IsSpace(next[0]))
                {
                    break;
                }

                if (length == MaxWordLength)
                {
                    throw Error($"a word longer than {MaxWordLength} characters, expected {expected}");
                }

                _bytes[length++] = (byte)input.ReadByte();
                _column++;
            }

            return Encoding.UTF8.GetString(_bytes, 0, length);
        }

        public void Expect(string keyword)
        {
            string word = Next($"'{keyword}'");
            if (word != keyword)
            {
                throw Error($"expected '{keyword}', found '{word}'");
            }
        }

        public double Number()
        {
            string word = Next("a number");
            if (!double.TryParse(word, NumberStyles.Float, CultureInfo.InvariantCulture, out double value))
            {
                throw Error($"'{word}' is not a number");
            }

            return value;
        }

        /// <summary>A vertex coordinate: a number that must be finite.</summary>
        public double Coordinate(string where, char axis)
        {
            double value = Number();
            if (!double.IsFinite(value))
            {
                throw Error($"{where} has a non-finite {axis} ({value.ToString(CultureInfo.InvariantCulture)})");
            }

            return value;
        }

        public void SkipRestOfLine()
        {
            if (_peeked is not null)
            {
                throw new InvalidOperationException("A peeked word cannot be skipped with the rest of its line.");
            }

            while (input.Peek(1) is [not (byte)'\n'])
            {
                input.ReadByte();
                _column++;
            }
        }

        private static bool IsSpace(byte b) => b is (byte)' ' or (byte)'\t' or (byte)'\r' or (byte)'\n' or 0x0B or 0x0C;

        /// <summary>Skips white space; false at the end of the file.</summary>
        private bool SkipSpace()
        {
            while (true)
            {
                var next = input.Peek(1);
                if (next.Length == 0)
                {
                    return false;
                }

                if (!IsSpace(next[0]))
                {
                    return true;
                }

                if (input.ReadByte() == '\n')
                {
                    _line++;
                    _column = 1;
                }
                else
                {
                    _column++;
                }
            }
        }
    }
}
