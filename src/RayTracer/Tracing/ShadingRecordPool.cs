namespace RayTracer.Tracing;

/// <summary>
/// Shading records reused by the calling thread, so tracing a ray allocates nothing. A ray traced while
/// its parent's record is still being shaded (a reflection, a refraction, a path bounce) takes the next
/// record up: records are handed out as a stack, one per level of nesting, each allocated once per thread.
/// </summary>
internal static class ShadingRecordPool
{
    [ThreadStatic]
    private static ShadingRecord[]? _records;

    [ThreadStatic]
    private static int _inUse;

    /// <summary>The record for the next level of nesting; the caller hands it back with <see cref="Return"/>.</summary>
    public static ShadingRecord Rent()
    {
        var records = _records ??= new ShadingRecord[8];
        if (_inUse == records.Length)
            _records = records = GrowTo(records, 2 * records.Length);
        return records[_inUse++] ??= new ShadingRecord();
    }

    /// <summary>Gives back the record most recently rented on this thread.</summary>
    public static void Return() => _inUse--;

    private static ShadingRecord[] GrowTo(ShadingRecord[] records, int length)
    {
        Array.Resize(ref records, length);
        return records;
    }
}
