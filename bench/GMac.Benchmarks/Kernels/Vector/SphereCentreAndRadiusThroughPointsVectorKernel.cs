using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>SphereCentreAndRadiusThroughPoints over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class SphereCentreAndRadiusThroughPointsVectorKernel() : VectorKernel(new SphereCentreAndRadiusThroughPointsKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns P1 = new(i, 0);
        Vec3Columns P2 = new(i, 3);
        Vec3Columns P3 = new(i, 6);
        Vec3Columns P4 = new(i, 9);
        var Radius = o[0];
        #region GMac : SphereCentreAndRadiusThroughPoints
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "Point3D", "P1[k]");
        //GMac.Bind("p2", "Point3D", "P2[k]");
        //GMac.Bind("p3", "Point3D", "P3[k]");
        //GMac.Bind("p4", "Point3D", "P4[k]");
        //GMac.Bind("radius.1", "<Radius[k]>");
        int count0 = P1.x.Length;
        if (P1.y.Length != count0 || P1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || P3.x.Length != count0 || P3.y.Length != count0 || P3.z.Length != count0 || P4.x.Length != count0 || P4.y.Length != count0 || P4.z.Length != count0 || Radius.Length != count0) throw new global::System.ArgumentException("SphereCentreAndRadiusThroughPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, P2.x, P2.y, P2.z, P3.x, P3.y, P3.z, P4.x, P4.y, P4.z, Radius");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P3.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P3.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P3.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P4.x);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P4.y);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P4.z);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Radius);
        var tmpC0 = Vector256.Create(0.5);
        int k = 0;
        for (; k <= count0 - Vector256<double>.Count; k += Vector256<double>.Count)
        {
            var item0 = Vector256.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector256.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector256.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector256.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector256.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector256.LoadUnsafe(ref span5, (nuint)k);
            var item6 = Vector256.LoadUnsafe(ref span6, (nuint)k);
            var item7 = Vector256.LoadUnsafe(ref span7, (nuint)k);
            var item8 = Vector256.LoadUnsafe(ref span8, (nuint)k);
            var item9 = Vector256.LoadUnsafe(ref span9, (nuint)k);
            var item10 = Vector256.LoadUnsafe(ref span10, (nuint)k);
            var item11 = Vector256.LoadUnsafe(ref span11, (nuint)k);
            var tmp0 = item3 - item0;
            var tmp1 = item4 - item1;
            var tmp2 = item5 - item2;
            var tmp3 = item6 - item0;
            var tmp4 = item7 - item1;
            var tmp5 = item8 - item2;
            var tmp6 = item9 - item0;
            var tmp7 = item10 - item1;
            var tmp8 = item11 - item2;
            var tmp9 = tmp0 * tmp4 - tmp1 * tmp3;
            var tmp10 = tmp0 * tmp5 - tmp2 * tmp3;
            var tmp11 = tmp1 * tmp5 - tmp2 * tmp4;
            var tmp12 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            var tmp13 = tmp3 * tmp3 + tmp4 * tmp4 + tmp5 * tmp5;
            var tmp14 = tmp6 * tmp6 + tmp7 * tmp7 + tmp8 * tmp8;
            var tmp15 = tmpC0 / (tmp11 * tmp6 + tmp8 * tmp9 - tmp10 * tmp7);
            var tmp16 = (tmp12 * (tmp4 * tmp8 - tmp5 * tmp7) + tmp13 * (tmp2 * tmp7 - tmp1 * tmp8) + tmp11 * tmp14) * tmp15;
            var tmp17 = (tmp12 * (tmp5 * tmp6 - tmp3 * tmp8) + tmp13 * (tmp0 * tmp8 - tmp2 * tmp6) - tmp10 * tmp14) * tmp15;
            var tmp18 = (tmp12 * (tmp3 * tmp7 - tmp4 * tmp6) + tmp13 * (tmp1 * tmp6 - tmp0 * tmp7) + tmp14 * tmp9) * tmp15;
            var result0 = Vector256.Sqrt(tmp16 * tmp16 + tmp17 * tmp17 + tmp18 * tmp18);
            Vector256.StoreUnsafe(result0, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P2.x[k] - P1.x[k];
            double tmp1 = P2.y[k] - P1.y[k];
            double tmp2 = P2.z[k] - P1.z[k];
            double tmp3 = P3.x[k] - P1.x[k];
            double tmp4 = P3.y[k] - P1.y[k];
            double tmp5 = P3.z[k] - P1.z[k];
            double tmp6 = P4.x[k] - P1.x[k];
            double tmp7 = P4.y[k] - P1.y[k];
            double tmp8 = P4.z[k] - P1.z[k];
            double tmp9 = tmp0 * tmp4 - tmp1 * tmp3;
            double tmp10 = tmp0 * tmp5 - tmp2 * tmp3;
            double tmp11 = tmp1 * tmp5 - tmp2 * tmp4;
            double tmp12 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            double tmp13 = tmp3 * tmp3 + tmp4 * tmp4 + tmp5 * tmp5;
            double tmp14 = tmp6 * tmp6 + tmp7 * tmp7 + tmp8 * tmp8;
            double tmp15 = 0.5 / (tmp11 * tmp6 + tmp8 * tmp9 - tmp10 * tmp7);
            double tmp16 = (tmp12 * (tmp4 * tmp8 - tmp5 * tmp7) + tmp13 * (tmp2 * tmp7 - tmp1 * tmp8) + tmp11 * tmp14) * tmp15;
            double tmp17 = (tmp12 * (tmp5 * tmp6 - tmp3 * tmp8) + tmp13 * (tmp0 * tmp8 - tmp2 * tmp6) - tmp10 * tmp14) * tmp15;
            double tmp18 = (tmp12 * (tmp3 * tmp7 - tmp4 * tmp6) + tmp13 * (tmp1 * tmp6 - tmp0 * tmp7) + tmp14 * tmp9) * tmp15;
            Radius[k] = Math.Sqrt(tmp16 * tmp16 + tmp17 * tmp17 + tmp18 * tmp18);
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns P1 = new(i, 0);
        Vec3Columns P2 = new(i, 3);
        Vec3Columns P3 = new(i, 6);
        Vec3Columns P4 = new(i, 9);
        var Radius = o[0];
        #region GMac : SphereCentreAndRadiusThroughPoints
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "Point3D", "P1[k]");
        //GMac.Bind("p2", "Point3D", "P2[k]");
        //GMac.Bind("p3", "Point3D", "P3[k]");
        //GMac.Bind("p4", "Point3D", "P4[k]");
        //GMac.Bind("radius.1", "<Radius[k]>");
        int count0 = P1.x.Length;
        if (P1.y.Length != count0 || P1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || P3.x.Length != count0 || P3.y.Length != count0 || P3.z.Length != count0 || P4.x.Length != count0 || P4.y.Length != count0 || P4.z.Length != count0 || Radius.Length != count0) throw new global::System.ArgumentException("SphereCentreAndRadiusThroughPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, P2.x, P2.y, P2.z, P3.x, P3.y, P3.z, P4.x, P4.y, P4.z, Radius");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P3.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P3.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P3.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P4.x);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P4.y);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P4.z);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Radius);
        var tmpC0 = Vector512.Create(0.5);
        int k = 0;
        for (; k <= count0 - Vector512<double>.Count; k += Vector512<double>.Count)
        {
            var item0 = Vector512.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector512.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector512.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector512.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector512.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector512.LoadUnsafe(ref span5, (nuint)k);
            var item6 = Vector512.LoadUnsafe(ref span6, (nuint)k);
            var item7 = Vector512.LoadUnsafe(ref span7, (nuint)k);
            var item8 = Vector512.LoadUnsafe(ref span8, (nuint)k);
            var item9 = Vector512.LoadUnsafe(ref span9, (nuint)k);
            var item10 = Vector512.LoadUnsafe(ref span10, (nuint)k);
            var item11 = Vector512.LoadUnsafe(ref span11, (nuint)k);
            var tmp0 = item3 - item0;
            var tmp1 = item4 - item1;
            var tmp2 = item5 - item2;
            var tmp3 = item6 - item0;
            var tmp4 = item7 - item1;
            var tmp5 = item8 - item2;
            var tmp6 = item9 - item0;
            var tmp7 = item10 - item1;
            var tmp8 = item11 - item2;
            var tmp9 = tmp0 * tmp4 - tmp1 * tmp3;
            var tmp10 = tmp0 * tmp5 - tmp2 * tmp3;
            var tmp11 = tmp1 * tmp5 - tmp2 * tmp4;
            var tmp12 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            var tmp13 = tmp3 * tmp3 + tmp4 * tmp4 + tmp5 * tmp5;
            var tmp14 = tmp6 * tmp6 + tmp7 * tmp7 + tmp8 * tmp8;
            var tmp15 = tmpC0 / (tmp11 * tmp6 + tmp8 * tmp9 - tmp10 * tmp7);
            var tmp16 = (tmp12 * (tmp4 * tmp8 - tmp5 * tmp7) + tmp13 * (tmp2 * tmp7 - tmp1 * tmp8) + tmp11 * tmp14) * tmp15;
            var tmp17 = (tmp12 * (tmp5 * tmp6 - tmp3 * tmp8) + tmp13 * (tmp0 * tmp8 - tmp2 * tmp6) - tmp10 * tmp14) * tmp15;
            var tmp18 = (tmp12 * (tmp3 * tmp7 - tmp4 * tmp6) + tmp13 * (tmp1 * tmp6 - tmp0 * tmp7) + tmp14 * tmp9) * tmp15;
            var result0 = Vector512.Sqrt(tmp16 * tmp16 + tmp17 * tmp17 + tmp18 * tmp18);
            Vector512.StoreUnsafe(result0, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P2.x[k] - P1.x[k];
            double tmp1 = P2.y[k] - P1.y[k];
            double tmp2 = P2.z[k] - P1.z[k];
            double tmp3 = P3.x[k] - P1.x[k];
            double tmp4 = P3.y[k] - P1.y[k];
            double tmp5 = P3.z[k] - P1.z[k];
            double tmp6 = P4.x[k] - P1.x[k];
            double tmp7 = P4.y[k] - P1.y[k];
            double tmp8 = P4.z[k] - P1.z[k];
            double tmp9 = tmp0 * tmp4 - tmp1 * tmp3;
            double tmp10 = tmp0 * tmp5 - tmp2 * tmp3;
            double tmp11 = tmp1 * tmp5 - tmp2 * tmp4;
            double tmp12 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            double tmp13 = tmp3 * tmp3 + tmp4 * tmp4 + tmp5 * tmp5;
            double tmp14 = tmp6 * tmp6 + tmp7 * tmp7 + tmp8 * tmp8;
            double tmp15 = 0.5 / (tmp11 * tmp6 + tmp8 * tmp9 - tmp10 * tmp7);
            double tmp16 = (tmp12 * (tmp4 * tmp8 - tmp5 * tmp7) + tmp13 * (tmp2 * tmp7 - tmp1 * tmp8) + tmp11 * tmp14) * tmp15;
            double tmp17 = (tmp12 * (tmp5 * tmp6 - tmp3 * tmp8) + tmp13 * (tmp0 * tmp8 - tmp2 * tmp6) - tmp10 * tmp14) * tmp15;
            double tmp18 = (tmp12 * (tmp3 * tmp7 - tmp4 * tmp6) + tmp13 * (tmp1 * tmp6 - tmp0 * tmp7) + tmp14 * tmp9) * tmp15;
            Radius[k] = Math.Sqrt(tmp16 * tmp16 + tmp17 * tmp17 + tmp18 * tmp18);
        }
        #endregion
    }
}
