namespace Twister.Tessellation;

/// <summary>
/// Finds the closed directions and poles of a surface by comparing its sides at the grid parameters
/// and a few random ones. Sides count as meeting when they agree within a billionth of the surface's
/// size, which rounding allows and a real gap does not. Only straight identifications are found
/// (u = 0 with u = 1 at the same v, and so on); a surface that closes with a twist, like a Möbius
/// strip, keeps an open seam.
/// </summary>
internal static class SeamDetector
{
    private const double RelativeWeldDistance = 1e-9;
    private const int RandomChecks = 3;

    public static Seams Detect(SurfaceSampler sampler, int cells, ProbeRandom random)
    {
        var n = cells;
        double minX = double.MaxValue, minY = double.MaxValue, minZ = double.MaxValue;
        double maxX = double.MinValue, maxY = double.MinValue, maxZ = double.MinValue;
        var normalScale = 0.0;
        for (var i = 0; i <= n; i++)
        {
            for (var j = 0; j <= n; j++)
            {
                var p = sampler.Point((double)i / n, (double)j / n);
                (minX, minY, minZ) = (Math.Min(minX, p.x), Math.Min(minY, p.y), Math.Min(minZ, p.z));
                (maxX, maxY, maxZ) = (Math.Max(maxX, p.x), Math.Max(maxY, p.y), Math.Max(maxZ, p.z));
                normalScale = Math.Max(normalScale, Geometry3.Length(sampler.RawNormal((double)i / n, (double)j / n)));
                if (i < n && j < n)
                {
                    normalScale = Math.Max(normalScale, Geometry3.Length(sampler.RawNormal((i + 0.5) / n, (j + 0.5) / n)));
                }
            }
        }

        var size = Math.Sqrt((maxX - minX) * (maxX - minX) + (maxY - minY) * (maxY - minY) + (maxZ - minZ) * (maxZ - minZ));
        if (!(size > 0) || !(normalScale > 0))
        {
            throw new TessellationException("The surface is degenerate: its normal vanishes on the whole starting grid (it is a point or a curve, not a surface).");
        }

        var weld = RelativeWeldDistance * size;
        var checks = Enumerable.Range(0, n + 1).Select(k => (double)k / n)
            .Concat(Enumerable.Range(0, RandomChecks).Select(_ => random.NextDouble())).ToArray();
        bool Same(double u0, double v0, double u1, double v1) =>
            Geometry3.Distance(sampler.Point(u0, v0), sampler.Point(u1, v1)) <= weld;

        return new Seams(n)
        {
            ClosedU = checks.All(t => Same(0, t, 1, t)),
            ClosedV = checks.All(t => Same(t, 0, t, 1)),
            PoleU0 = checks.All(t => Same(0, t, 0, 0)),
            PoleU1 = checks.All(t => Same(1, t, 1, 0)),
            PoleV0 = checks.All(t => Same(t, 0, 0, 0)),
            PoleV1 = checks.All(t => Same(t, 1, 0, 1)),
            NormalScale = normalScale,
        };
    }
}
