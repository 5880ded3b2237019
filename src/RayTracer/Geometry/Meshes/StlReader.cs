using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using RayTracer.Maths;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Reads STL files (ASCII and binary) into an indexed mesh. STL stores every triangle with its own
/// corners, so identical corner positions are merged into shared vertices (needed for smooth
/// normals). Facet normals in the file are ignored; the winding defines the orientation.
/// A file is binary when its size is exactly 84 + 50 n for the n in its header, else it must be ASCII.
/// </summary>
public static class StlReader
{
    public static Mesh Read(string path)
    {
        using var stream = File.OpenRead(path);
        return Read(stream, Path.GetFileName(path));
    }

    public static Mesh Read(Stream stream, string fileName)
    {
        ArgumentNullException.ThrowIfNull(stream);
        byte[] data;
        using (var memory = new MemoryStream())
        {
            stream.CopyTo(memory);
            data = memory.ToArray();
        }

        if (data.Length == 0)
        {
            throw new MeshFormatException(fileName, "the file is empty; an STL file starts with 'solid' (ASCII) or an 84-byte header (binary)", 1, column: 1);
        }

        // The declared triangle count must match the file size exactly, so it can never drive a loop past the data.
        if (data.Length >= 84)
        {
            uint count = BinaryPrimitives.ReadUInt32LittleEndian(data.AsSpan(80));
            if (84 + 50L * count == data.Length)
            {
                return ReadBinary(data, count, fileName);
            }
        }

        if (LooksLikeAscii(data))
        {
            return ReadAscii(data, fileName);
        }

        if (data.Length < 84)
        {
            throw new MeshFormatException(fileName, "too short for a binary STL header and not ASCII STL", null, data.Length);
        }

        uint declared = BinaryPrimitives.ReadUInt32LittleEndian(data.AsSpan(80));
        long expected = 84 + 50L * declared;
        long complete = (data.Length - 84) / 50;
        throw new MeshFormatException(
            fileName,
            data.Length < expected
                ? $"binary STL declares {declared} triangles ({expected} bytes) but the file ends inside triangle {complete}"
                : $"binary STL declares {declared} triangles ({expected} bytes) but the file has {data.Length} bytes",
            null,
            Math.Min(data.Length, expected));
    }

    private static bool LooksLikeAscii(byte[] data)
    {
        int i = 0;
        while (i < data.Length && data[i] is (byte)' ' or (byte)'\t' or (byte)'\r' or (byte)'\n')
        {
            i++;
        }

        return data.AsSpan(i).StartsWith("solid"u8);
    }

    private static Mesh ReadBinary(byte[] data, uint count, string fileName)
    {
        var builder = new VertexMerger();
        for (long f = 0; f < count; f++)
        {
            long at = 84 + 50 * f + 12;
            for (int k = 0; k < 3; k++)
            {
                int start = (int)(at + 12 * k);
                ReadOnlySpan<byte> s = data.AsSpan(start, 12);
                for (int c = 0; c < 3; c++)
                {
                    float value = BinaryPrimitives.ReadSingleLittleEndian(s[(4 * c)..]);
                    if (!float.IsFinite(value))
                    {
                        throw new MeshFormatException(
                            fileName, $"triangle {f} vertex {k} has a non-finite {"xyz"[c]} ({value.ToString(CultureInfo.InvariantCulture)})", null, start + 4 * c);
                    }
                }

                builder.Add(new Point3D(
                    BinaryPrimitives.ReadSingleLittleEndian(s),
                    BinaryPrimitives.ReadSingleLittleEndian(s[4..]),
                    BinaryPrimitives.ReadSingleLittleEndian(s[8..])));
            }
        }

        return builder.ToMesh();
    }

    private static Mesh ReadAscii(byte[] data, string fileName)
    {
        var tokens = new AsciiTokens(Encoding.ASCII.GetString(data), fileName);
        var builder = new VertexMerger();
        tokens.Expect("solid");
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

    private sealed class VertexMerger
    {
        private readonly Dictionary<Point3D, int> _index = [];
        private readonly List<Point3D> _vertices = [];
        private readonly List<int> _indices = [];

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

    /// <summary>Whitespace-separated words with line numbers for messages.</summary>
    private sealed class AsciiTokens(string text, string fileName)
    {
        private int _pos;
        private int _line = 1;
        private int _tokenLine = 1;

        public bool AtEnd
        {
            get
            {
                SkipSpace();
                return _pos >= text.Length;
            }
        }

        public MeshFormatException Error(string problem) => new(fileName, problem, _tokenLine);

        public string? Peek()
        {
            int pos = _pos, line = _line;
            string? word = AtEnd ? null : Next("a word");
            _pos = pos;
            _line = line;
            return word;
        }

        public string Next(string expected)
        {
            SkipSpace();
            _tokenLine = _line;
            if (_pos >= text.Length)
            {
                throw new MeshFormatException(fileName, $"unexpected end of file, expected {expected}", _line);
            }

            int start = _pos;
            while (_pos < text.Length && !char.IsWhiteSpace(text[_pos]))
            {
                _pos++;
            }

            return text[start.._pos];
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
            while (_pos < text.Length && text[_pos] != '\n')
            {
                _pos++;
            }
        }

        private void SkipSpace()
        {
            while (_pos < text.Length && char.IsWhiteSpace(text[_pos]))
            {
                if (text[_pos] == '\n')
                {
                    _line++;
                }

                _pos++;
            }
        }
    }
}
