using GMac.Benchmarks.Kernels.Vector;

namespace GMac.Benchmarks.Tests.Kernels;

/// <summary>The vector kernels' columns start on 64-byte boundaries, whatever their length, and are distinct arrays.</summary>
public class AlignedColumns_StartOnCacheLines
{
    [Theory]
    [InlineData(1)]
    [InlineData(37)]
    [InlineData(256)]
    [InlineData(1024)]
    [InlineData(20000)] // large enough for the large-object part of the pinned heap's neighbours
    public void Every_column_starts_a_cache_line(int length)
    {
        var columns = AlignedColumns.Allocate(9, length);
        Assert.Equal(9, columns.Length);
        Assert.All(columns, c => Assert.Equal(length, c.Length));
        Assert.All(columns, c => Assert.Equal(0u, AlignedColumns.Address(c) % 64));
        Assert.Equal(9, columns.Distinct().Count());
    }

    [Fact]
    public void A_kernel_counts_the_columns_it_reads_and_writes()
    {
        var kernel = VectorKernelCatalog.CreateAll().Single(k => k.MacroName == "SquaredDistance");
        kernel.Setup(100, seed: 3);
        Assert.Equal(7, kernel.ColumnCount);
    }
}
