using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using RayTracer.Maths;
using RayTracer.Textures;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Reads triangle meshes from PLY files (ASCII, binary little and big endian). Vertex x, y, z are
/// required; nx, ny, nz and u, v (or s, t) are picked up when present. Polygons are split into
/// triangle fans; other elements and properties are skipped. Problems raise
/// <see cref="MeshFormatException"/> with the line (ASCII) or byte offset (binary). Unknown header lines
/// (some exporters write free text without 'comment') are skipped and listed in <see cref="Mesh.Warnings"/>.
/// </summary>
public static class PlyReader
{
    private const int MaxHeaderBytes = 1 << 20;

    /// <summary>2^53: up to here every integer is exact as a double.</summary>
    private const double MaxExactInteger = 9007199254740992;

    public static Mesh Read(string path)
    {
        using var stream = File.OpenRead(path);
        return Read(stream, Path.GetFileName(path));
    }

    public static Mesh Read(Stream stream, string fileName)
    {
        ArgumentNullException.ThrowIfNull(stream);
        long? length = stream.CanSeek ? stream.Length - stream.Position : null;
        var input = new PlyInput(new BufferedStream(stream, 1 << 16), fileName, length);
        var header = ReadHeader(input);
        return ReadBody(input, header);
    }

    private enum Scalar
    {
        Int8,
        UInt8,
        Int16,
        UInt16,
        Int32,
        UInt32,
        Float32,
        Float64,
    }

    private sealed record Property(string Name, Scalar Type, bool IsList, Scalar CountType);

    private sealed class Element(string name, long count, int line)
    {
        public string Name { get; } = name;

        public long Count { get; } = count;

        public int Line { get; } = line;

        public List<Property> Properties { get; } = [];
    }

    private sealed class Header
    {
        public PlyFormat Format { get; set; }

        public List<Element> Elements { get; } = [];

        public List<string> Warnings { get; } = [];
    }

    private static Header ReadHeader(PlyInput input)
    {
        var header = new Header();
        string? magic = input.ReadHeaderLine();
        if (magic is null)
        {
            throw new MeshFormatException(input.FileName, "the file is empty; a PLY file starts with the line 'ply'", 1, column: 1);
        }

        if (magic != "ply")
        {
            throw input.ErrorAtLine("not a PLY file: the first line must be 'ply'");
        }

        bool formatSeen = false;
        while (true)
        {
            string line = input.ReadHeaderLine() ?? throw input.ErrorAtLine("the header ends without 'end_header'");
            string[] words = line.Split(' ', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
            if (words.Length == 0)
            {
                continue;
            }

            switch (words[0])
            {
                case "comment":
                case "obj_info":
                    break;
                case "format":
                    if (words.Length != 3 || words[2] != "1.0")
                    {
                        throw input.ErrorAtLine($"unsupported format line '{line}'");
                    }

                    header.Format = words[1] switch
                    {
                        "ascii" => PlyFormat.Ascii,
                        "binary_little_endian" => PlyFormat.BinaryLittleEndian,
                        "binary_big_endian" => PlyFormat.BinaryBigEndian,
                        _ => throw input.ErrorAtLine($"unknown PLY format '{words[1]}'"),
                    };
                    formatSeen = true;
                    break;
                case "element":
                    if (words.Length != 3 || !long.TryParse(words[2], NumberStyles.None, CultureInfo.InvariantCulture, out long count))
                    {
                        throw input.ErrorAtLine($"malformed element line '{line}'");
                    }

                    header.Elements.Add(new Element(words[1], count, input.Line));
                    break;
                case "property":
                    if (header.Elements.Count == 0)
                    {
                        throw input.ErrorAtLine("property declared before any element");
                    }

                    header.Elements[^1].Properties.Add(ParseProperty(words, line, input));
                    break;
                case "end_header":
                    if (!formatSeen)
                    {
                        throw input.ErrorAtLine("the header has no 'format' line");
                    }

                    input.BeginBody(header.Format);
                    return header;
                default:
                    // Common readers skip such lines too (old Blender exports write "Created by ..." bare).
                    header.Warnings.Add($"{input.FileName}({input.Line}): skipped unknown header line '{line}'");
                    break;
            }
        }
    }

    private static Property ParseProperty(string[] words, string line, PlyInput input)
    {
        if (words.Length == 3)
        {
            return new Property(words[2], ParseScalar(words[1], input), false, Scalar.UInt8);
        }

        if (words.Length == 5 && words[1] == "list")
        {
            return new Property(words[4], ParseScalar(words[3], input), true, ParseScalar(words[2], input));
        }

        throw input.ErrorAtLine($"malformed property line '{line}'");
    }

    private static Scalar ParseScalar(string word, PlyInput input) => word switch
    {
        "char" or "int8" => Scalar.Int8,
        "uchar" or "uint8" => Scalar.UInt8,
        "short" or "int16" => Scalar.Int16,
        "ushort" or "uint16" => Scalar.UInt16,
        "int" or "int32" => Scalar.Int32,
        "uint" or "uint32" => Scalar.UInt32,
        "float" or "float32" => Scalar.Float32,
        "double" or "float64" => Scalar.Float64,
        _ => throw input.ErrorAtLine($"unknown property type '{word}'"),
    };

    private static Mesh ReadBody(PlyInput input, Header header)
    {
        var vertexElement = header.Elements.Find(e => e.Name == "vertex")
            ?? throw new MeshFormatException(input.FileName, "the header declares no 'vertex' element");
        int ix = vertexElement.Properties.FindIndex(p => p.Name == "x" && !p.IsList);
        int iy = vertexElement.Properties.FindIndex(p => p.Name == "y" && !p.IsList);
        int iz = vertexElement.Properties.FindIndex(p => p.Name == "z" && !p.IsList);
        if (ix < 0 || iy < 0 || iz < 0)
        {
            throw new MeshFormatException(input.FileName, "the vertex element lacks x, y or z", vertexElement.Line);
        }

        int inx = vertexElement.Properties.FindIndex(p => p.Name == "nx");
        int iny = vertexElement.Properties.FindIndex(p => p.Name == "ny");
        int inz = vertexElement.Properties.FindIndex(p => p.Name == "nz");
        bool hasNormals = inx >= 0 && iny >= 0 && inz >= 0;
        int iu = vertexElement.Properties.FindIndex(p => p.Name is "u" or "s" or "texture_u");
        int iv = vertexElement.Properties.FindIndex(p => p.Name is "v" or "t" or "texture_v");
        bool hasUvs = iu >= 0 && iv >= 0;

        if (vertexElement.Count > int.MaxValue)
        {
            throw new MeshFormatException(input.FileName, "too many vertices", vertexElement.Line);
        }

        // Lists grow as data arrives, so a header that declares absurd counts fails on the
        // truncated body instead of exhausting memory up front.
        int declaredVertices = (int)vertexElement.Count;
        int initial = Math.Min(declaredVertices, 1 << 16);
        var vertices = new List<Point3D>(initial);
        var normals = hasNormals ? new List<Normal3D>(initial) : null;
        var uvs = hasUvs ? new List<TextureCoordinates>(initial) : null;
        var indices = new List<int>();
        bool facesSeen = false;
        var values = new double[Math.Max(1, vertexElement.Properties.Count)];
        var mustBeFinite = new bool[values.Length];
        // NaN or infinite values would silently poison bounds, normals and texture lookups.
        foreach (int used in new[] { ix, iy, iz }.Concat(hasNormals ? [inx, iny, inz] : []).Concat(hasUvs ? [iu, iv] : []))
        {
            mustBeFinite[used] = true;
        }

        foreach (var element in header.Elements)
        {
            bool isVertex = ReferenceEquals(element, vertexElement);
            bool isFace = element.Name == "face" && !facesSeen;
            int listIndex = isFace
                ? element.Properties.FindIndex(p => p.IsList && p.Name is "vertex_indices" or "vertex_index")
                : -1;
            if (isFace)
            {
                if (listIndex < 0)
                {
                    throw new MeshFormatException(input.FileName, "the face element has no vertex_indices list", element.Line);
                }

                facesSeen = true;
            }

            if (element.Properties.Count == 0)
            {
                // Nothing to read, however large the count: looping over it would only spin.
                continue;
            }

            input.EnsureRoomFor(element);
            for (long i = 0; i < element.Count; i++)
            {
                for (int p = 0; p < element.Properties.Count; p++)
                {
                    var property = element.Properties[p];
                    if (!property.IsList)
                    {
                        long start = input.Offset;
                        double value = input.ReadScalar(property.Type, element.Name, i);
                        if (isVertex)
                        {
                            if (mustBeFinite[p] && !double.IsFinite(value))
                            {
                                throw input.ErrorHere(
                                    $"{element.Name} {i} has a non-finite {property.Name} ({value.ToString(CultureInfo.InvariantCulture)})", start);
                            }

                            values[p] = value;
                        }

                        continue;
                    }

                    long count = input.ReadInteger(property.CountType, element.Name, i);
                    if (count < 0)
                    {
                        throw input.ErrorHere($"negative list length in {element.Name} {i}");
                    }

                    input.EnsureRoomFor(count, property.Type, element.Name, i);
                    if (count > int.MaxValue)
                    {
                        throw input.ErrorHere($"a list in {element.Name} {i} declares {count} items, more than any PLY reader takes ({int.MaxValue})");
                    }

                    if (p == listIndex)
                    {
                        if (count < 3)
                        {
                            throw input.ErrorHere($"face {i} has {count} vertices; at least 3 are needed");
                        }

                        long first = input.ReadInteger(property.Type, element.Name, i);
                        long previous = input.ReadInteger(property.Type, element.Name, i);
                        for (long k = 2; k < count; k++)
                        {
                            long current = input.ReadInteger(property.Type, element.Name, i);
                            AddIndex(indices, first, declaredVertices, i, input);
                            AddIndex(indices, previous, declaredVertices, i, input);
                            AddIndex(indices, current, declaredVertices, i, input);
                            previous = current;
                        }
                    }
                    else
                    {
                        for (long k = 0; k < count; k++)
                        {
                            input.ReadScalar(property.Type, element.Name, i);
                        }
                    }
                }

                if (isVertex)
                {
                    vertices.Add(new Point3D(values[ix], values[iy], values[iz]));
                    normals?.Add(new Normal3D(values[inx], values[iny], values[inz]));
                    uvs?.Add(new TextureCoordinates(values[iu], values[iv]));
                }
            }
        }

        return new Mesh([.. vertices], [.. indices], normals?.ToArray(), uvs?.ToArray()) { Warnings = header.Warnings };
    }

    private static void AddIndex(List<int> indices, long index, int vertexCount, long face, PlyInput input)
    {
        if (index < 0 || index >= vertexCount)
        {
            throw input.ErrorHere($"face {face} refers to vertex {index}, but there are {vertexCount} vertices");
        }

        indices.Add((int)index);
    }

    /// <summary>Byte-level reader that knows the current line (text) and offset (binary) for messages.</summary>
    private sealed class PlyInput(Stream stream, string fileName, long? length)
    {
        private readonly byte[] _scratch = new byte[8];
        private readonly StringBuilder _token = new();
        private PlyFormat _format;
        private bool _pendingNewline;

        public string FileName { get; } = fileName;

        public int Line { get; private set; }

        public long Offset { get; private set; }

        public string? ReadHeaderLine()
        {
            var line = new StringBuilder();
            while (true)
            {
                int b = stream.ReadByte();
                if (b < 0)
                {
                    return line.Length == 0 ? null : Finish(line);
                }

                Offset++;
                if (Offset > MaxHeaderBytes)
                {
                    throw new MeshFormatException(FileName, "the header is too long (is 'end_header' missing?)", null, Offset);
                }

                if (b == '\n')
                {
                    return Finish(line);
                }

                if (b != '\r')
                {
                    line.Append((char)b);
                }
            }
        }

        public void BeginBody(PlyFormat format)
        {
            _format = format;
        }

        public MeshFormatException ErrorAtLine(string problem) => new(FileName, problem, Line);

        /// <summary>An error at the current token (ASCII) or at <paramref name="offset"/>, by default the current one (binary).</summary>
        public MeshFormatException ErrorHere(string problem, long? offset = null) =>
            _format == PlyFormat.Ascii ? new(FileName, problem, Line + 1) : new(FileName, problem, null, offset ?? Offset);

        /// <summary>
        /// In a binary file of known length, fails at once when the remaining bytes cannot hold every item
        /// of <paramref name="element"/>, rather than looping over a count a forged header made huge.
        /// ASCII items take at least one token each, so those loops end at the end of the file anyway.
        /// </summary>
        public void EnsureRoomFor(Element element)
        {
            if (_format == PlyFormat.Ascii || length is not { } total)
            {
                return;
            }

            // A list takes at least its length prefix; its items are checked when the length is known.
            long itemBytes = element.Properties.Sum(p => (long)Size(p.IsList ? p.CountType : p.Type));
            long remaining = total - Offset;
            if (element.Count > remaining / itemBytes)
            {
                throw new MeshFormatException(
                    FileName,
                    $"element '{element.Name}' declares {element.Count} items of at least {itemBytes} bytes, but only {remaining} bytes remain",
                    null,
                    Offset);
            }
        }

        /// <summary>Fails at once when a binary list claims more items than the rest of the file can hold.</summary>
        public void EnsureRoomFor(long count, Scalar type, string element, long index)
        {
            if (_format == PlyFormat.Ascii || length is not { } total)
            {
                return;
            }

            long remaining = total - Offset;
            if (count > remaining / Size(type))
            {
                throw ErrorHere($"a list in {element} {index} declares {count} items, but only {remaining} bytes remain");
            }
        }

        /// <summary>
        /// A whole number; its range is the caller's to check, so that it can say what the number is for
        /// (a list length, a vertex index). Every binary integer type fits a long exactly.
        /// </summary>
        public long ReadInteger(Scalar type, string element, long index)
        {
            long start = Offset;
            double value = ReadScalar(type, element, index);
            if (value != Math.Floor(value))
            {
                throw ErrorHere($"expected an integer in {element} {index}, found {value.ToString(CultureInfo.InvariantCulture)}", start);
            }

            // Only ASCII text can go beyond; a long holds every integer of the binary types.
            if (Math.Abs(value) > MaxExactInteger)
            {
                throw ErrorHere($"the integer {value.ToString(CultureInfo.InvariantCulture)} in {element} {index} is too large", start);
            }

            return (long)value;
        }

        public double ReadScalar(Scalar type, string element, long index)
        {
            if (_format == PlyFormat.Ascii)
            {
                string token = NextToken(element, index);
                if (!double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out double value))
                {
                    throw ErrorHere($"'{token}' is not a number (in {element} {index})");
                }

                return value;
            }

            int size = Size(type);
            var bytes = _scratch.AsSpan(0, size);
            int read = stream.ReadAtLeast(bytes, size, throwOnEndOfStream: false);
            if (read < size)
            {
                throw new MeshFormatException(
                    FileName, $"the file ends inside {element} {index}", null, Offset + read);
            }

            Offset += size;
            bool little = _format == PlyFormat.BinaryLittleEndian;
            return type switch
            {
                Scalar.Int8 => (sbyte)bytes[0],
                Scalar.UInt8 => bytes[0],
                Scalar.Int16 => little ? BinaryPrimitives.ReadInt16LittleEndian(bytes) : BinaryPrimitives.ReadInt16BigEndian(bytes),
                Scalar.UInt16 => little ? BinaryPrimitives.ReadUInt16LittleEndian(bytes) : BinaryPrimitives.ReadUInt16BigEndian(bytes),
                Scalar.Int32 => little ? BinaryPrimitives.ReadInt32LittleEndian(bytes) : BinaryPrimitives.ReadInt32BigEndian(bytes),
                Scalar.UInt32 => little ? BinaryPrimitives.ReadUInt32LittleEndian(bytes) : BinaryPrimitives.ReadUInt32BigEndian(bytes),
                Scalar.Float32 => little ? BinaryPrimitives.ReadSingleLittleEndian(bytes) : BinaryPrimitives.ReadSingleBigEndian(bytes),
                _ => little ? BinaryPrimitives.ReadDoubleLittleEndian(bytes) : BinaryPrimitives.ReadDoubleBigEndian(bytes),
            };
        }

        private static int Size(Scalar type) => type switch
        {
            Scalar.Int8 or Scalar.UInt8 => 1,
            Scalar.Int16 or Scalar.UInt16 => 2,
            Scalar.Int32 or Scalar.UInt32 or Scalar.Float32 => 4,
            _ => 8,
        };

        private string Finish(StringBuilder line)
        {
            Line++;
            return line.ToString();
        }

        private string NextToken(string element, long index)
        {
            if (_pendingNewline)
            {
                Line++;
                _pendingNewline = false;
            }

            _token.Clear();
            while (true)
            {
                int b = stream.ReadByte();
                if (b < 0)
                {
                    if (_token.Length > 0)
                    {
                        return _token.ToString();
                    }

                    throw new MeshFormatException(FileName, $"the file ends inside {element} {index}", Line + 1);
                }

                if (b is ' ' or '\t' or '\r' or '\n')
                {
                    if (_token.Length > 0)
                    {
                        if (b == '\n')
                        {
                            // Count this newline only on the next read, so an error in this token names its own line.
                            _pendingNewline = true;
                        }

                        return _token.ToString();
                    }

                    if (b == '\n')
                    {
                        Line++;
                    }

                    continue;
                }

                _token.Append((char)b);
            }
        }

    }
}
