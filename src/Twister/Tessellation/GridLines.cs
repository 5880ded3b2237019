namespace Twister.Tessellation;

/// <summary>
/// The vertices on each line of the parameter grid (u fixed or v fixed), so that a leaf finds every
/// sample that any face put on its sides, whatever the split that made it.
/// </summary>
internal sealed class GridLines
{
    private readonly Dictionary<long, List<(long At, int Id)>> _columns = [];
    private readonly Dictionary<long, List<(long At, int Id)>> _rows = [];

    public void Add(long i, long j, int id)
    {
        Line(_columns, i).Add((j, id));
        Line(_rows, j).Add((i, id));
    }

    /// <summary>Sorts every line; call once all vertices are made.</summary>
    public void Freeze()
    {
        foreach (var line in _columns.Values.Concat(_rows.Values))
        {
            line.Sort((x, y) => x.At.CompareTo(y.At));
        }
    }

    /// <summary>Adds the vertices strictly between grid points (i0, j0) and (i1, j1) of one row or column, in order from the first.</summary>
    public void Between(long i0, long j0, long i1, long j1, List<BoundaryVertex> output)
    {
        var alongU = j0 == j1;
        var line = alongU ? _rows[j0] : _columns[i0];
        long from = alongU ? i0 : j0, to = alongU ? i1 : j1;
        var (low, high) = (Math.Min(from, to), Math.Max(from, to));
        var start = Find(line, low) + 1;
        var end = Find(line, high);
        var count = output.Count;
        for (var k = start; k < end; k++)
        {
            var (at, id) = line[k];
            output.Add(alongU ? new(id, at, j0) : new(id, i0, at));
        }

        if (from > to)
        {
            output.Reverse(count, output.Count - count);
        }
    }

    /// <summary>Index of the vertex at <paramref name="at"/>, which is on the line.</summary>
    private static int Find(List<(long At, int Id)> line, long at)
    {
        int low = 0, high = line.Count - 1;
        while (low <= high)
        {
            var mid = (low + high) / 2;
            if (line[mid].At < at)
            {
                low = mid + 1;
            }
            else if (line[mid].At > at)
            {
                high = mid - 1;
            }
            else
            {
                return mid;
            }
        }

        throw new InvalidOperationException("A cell corner is missing from its grid line.");
    }

    private static List<(long At, int Id)> Line(Dictionary<long, List<(long At, int Id)>> lines, long key)
    {
        if (!lines.TryGetValue(key, out var line))
        {
            line = [];
            lines[key] = line;
        }

        return line;
    }
}
