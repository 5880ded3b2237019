using System.Runtime.InteropServices;
using RayTracer.Acceleration.Embree;

namespace RayTracer.Tests.Acceleration;

/// <summary>
/// The binding's structs against Embree 3's headers (rtcore_ray.h, rtcore_common.h) as the Debian package
/// builds them: one instance level, no minimum curve width. No Embree is needed to check them.
/// </summary>
public class EmbreeBinding_Layout
{
    [Theory]
    [InlineData("OrgX", 0)]
    [InlineData("OrgY", 4)]
    [InlineData("OrgZ", 8)]
    [InlineData("TNear", 12)]
    [InlineData("DirX", 16)]
    [InlineData("DirY", 20)]
    [InlineData("DirZ", 24)]
    [InlineData("Time", 28)]
    [InlineData("TFar", 32)]
    [InlineData("Mask", 36)]
    [InlineData("Id", 40)]
    [InlineData("Flags", 44)]
    public void Ray_fields_sit_where_the_native_ray_has_them(string field, int offset) =>
        Assert.Equal(offset, (int)Marshal.OffsetOf<EmbreeRay>(field));

    [Theory]
    [InlineData("NgX", 0)]
    [InlineData("NgY", 4)]
    [InlineData("NgZ", 8)]
    [InlineData("U", 12)]
    [InlineData("V", 16)]
    [InlineData("PrimId", 20)]
    [InlineData("GeomId", 24)]
    [InlineData("InstId0", 28)]
    public void Hit_fields_sit_where_the_native_hit_has_them(string field, int offset) =>
        Assert.Equal(offset, (int)Marshal.OffsetOf<EmbreeHit>(field));

    [Fact]
    public void Sizes_include_the_padding_of_sixteen_byte_alignment()
    {
        Assert.Equal(48, Marshal.SizeOf<EmbreeRay>());
        Assert.Equal(32, Marshal.SizeOf<EmbreeHit>());
        Assert.Equal(80, Marshal.SizeOf<EmbreeRayHit>());
        Assert.Equal(0, (int)Marshal.OffsetOf<EmbreeRayHit>(nameof(EmbreeRayHit.Ray)));
        Assert.Equal(48, (int)Marshal.OffsetOf<EmbreeRayHit>(nameof(EmbreeRayHit.Hit)));
        Assert.Equal(0, Marshal.SizeOf<EmbreeRay>() % 16);
        Assert.Equal(0, Marshal.SizeOf<EmbreeHit>() % 16);
    }

    [Fact]
    public void Context_is_flags_filter_and_one_instance_id()
    {
        Assert.Equal(0, (int)Marshal.OffsetOf<EmbreeIntersectContext>(nameof(EmbreeIntersectContext.Flags)));
        Assert.Equal(8, (int)Marshal.OffsetOf<EmbreeIntersectContext>(nameof(EmbreeIntersectContext.Filter)));
        Assert.Equal(16, (int)Marshal.OffsetOf<EmbreeIntersectContext>(nameof(EmbreeIntersectContext.InstId0)));
        Assert.Equal(24, Marshal.SizeOf<EmbreeIntersectContext>());
        var context = EmbreeIntersectContext.Incoherent;
        Assert.Equal(0, context.Flags);
        Assert.Equal(0, context.Filter);
        Assert.Equal(uint.MaxValue, context.InstId0);
    }

    [Fact]
    public void Packets_of_eight_hold_each_field_for_eight_rays()
    {
        string[] rayFields = ["OrgX", "OrgY", "OrgZ", "TNear", "DirX", "DirY", "DirZ", "Time", "TFar", "Mask", "Id", "Flags"];
        for (int i = 0; i < rayFields.Length; i++)
            Assert.Equal(32 * i, (int)Marshal.OffsetOf<EmbreeRay8>(rayFields[i]));
        string[] hitFields = ["NgX", "NgY", "NgZ", "U", "V", "PrimId", "GeomId", "InstId0"];
        for (int i = 0; i < hitFields.Length; i++)
            Assert.Equal(32 * i, (int)Marshal.OffsetOf<EmbreeHit8>(hitFields[i]));
        Assert.Equal(384, Marshal.SizeOf<EmbreeRay8>());
        Assert.Equal(256, Marshal.SizeOf<EmbreeHit8>());
        Assert.Equal(640, Marshal.SizeOf<EmbreeRayHit8>());
        Assert.Equal(384, (int)Marshal.OffsetOf<EmbreeRayHit8>(nameof(EmbreeRayHit8.Hit)));
    }
}
