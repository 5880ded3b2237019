using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>SphereThroughPoints over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed partial class SphereThroughPointsVectorKernel() : VectorKernel(new SphereThroughPointsKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns P1 = new(i, 0);
        Vec3Columns P2 = new(i, 3);
        Vec3Columns P3 = new(i, 6);
        Vec3Columns P4 = new(i, 9);
        var No = o[0];
        var E1 = o[1];
        var E2 = o[2];
        var E3 = o[3];
        var Ni = o[4];
        #region GMac : SphereThroughPoints
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "ConformalPoint3D", "P1[k]");
        //GMac.Bind("p2", "ConformalPoint3D", "P2[k]");
        //GMac.Bind("p3", "ConformalPoint3D", "P3[k]");
        //GMac.Bind("p4", "ConformalPoint3D", "P4[k]");
        //GMac.Bind("omega.no", "<No[k]>");
        //GMac.Bind("omega.e1", "<E1[k]>");
        //GMac.Bind("omega.e2", "<E2[k]>");
        //GMac.Bind("omega.e3", "<E3[k]>");
        //GMac.Bind("omega.ni", "<Ni[k]>");
        int count0 = P1.x.Length;
        if (P1.y.Length != count0 || P1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || P3.x.Length != count0 || P3.y.Length != count0 || P3.z.Length != count0 || P4.x.Length != count0 || P4.y.Length != count0 || P4.z.Length != count0 || E2.Length != count0 || E3.Length != count0 || No.Length != count0 || E1.Length != count0 || Ni.Length != count0) throw new global::System.ArgumentException("SphereThroughPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, P2.x, P2.y, P2.z, P3.x, P3.y, P3.z, P4.x, P4.y, P4.z, E2, E3, No, E1, Ni");
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
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E2);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E3);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)No);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E1);
        ref double span16 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Ni);
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
            var tmp3 = tmpC0 * (tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2);
            var tmp4 = item6 - item0;
            var tmp5 = item7 - item1;
            var tmp6 = item8 - item2;
            var tmp7 = tmpC0 * (tmp4 * tmp4 + tmp5 * tmp5 + tmp6 * tmp6);
            var tmp8 = item9 - item0;
            var tmp9 = item10 - item1;
            var tmp10 = tmp9 * tmp4 - tmp8 * tmp5;
            var tmp11 = item11 - item2;
            var tmp12 = tmpC0 * (tmp8 * tmp8 + tmp9 * tmp9 + tmp11 * tmp11);
            var tmp13 = tmp12 * tmp4 - tmp8 * tmp7;
            var tmp14 = tmp12 * tmp5 - tmp9 * tmp7;
            var tmp15 = tmp13 * tmp1 - (tmp14 * tmp0 + tmp3 * tmp10);
            var tmp16 = tmp12 * tmp6 - tmp11 * tmp7;
            var tmp17 = tmp11 * tmp4 - tmp8 * tmp6;
            var tmp18 = tmp16 * tmp0 + tmp3 * tmp17 - tmp13 * tmp2;
            var tmp19 = tmp11 * tmp5 - tmp9 * tmp6;
            var tmp20 = tmp1 * tmp17 - (tmp19 * tmp0 + tmp2 * tmp10);
            var tmp21 = tmp18 + tmp20 * item1;
            var result0 = tmp21;
            var tmp22 = tmp20 * item2 + tmp15;
            var result1 = tmp22;
            var result2 = tmp20;
            var tmp23 = tmp19 * tmp3 + tmp16 * tmp1 - tmp14 * tmp2;
            var tmp24 = tmp20 * item0 - tmp23;
            var result3 = tmp24;
            var result4 = tmpC0 * (item0 * (tmp24 - tmp23) + item1 * (tmp18 + tmp21) + item2 * (tmp22 + tmp15));
            Vector256.StoreUnsafe(result0, ref span12, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span13, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span14, (nuint)k);
            Vector256.StoreUnsafe(result3, ref span15, (nuint)k);
            Vector256.StoreUnsafe(result4, ref span16, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P2.x[k] - P1.x[k];
            double tmp1 = P2.y[k] - P1.y[k];
            double tmp2 = P2.z[k] - P1.z[k];
            double tmp3 = 0.5 * (tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2);
            double tmp4 = P3.x[k] - P1.x[k];
            double tmp5 = P3.y[k] - P1.y[k];
            double tmp6 = P3.z[k] - P1.z[k];
            double tmp7 = 0.5 * (tmp4 * tmp4 + tmp5 * tmp5 + tmp6 * tmp6);
            double tmp8 = P4.x[k] - P1.x[k];
            double tmp9 = P4.y[k] - P1.y[k];
            double tmp10 = tmp9 * tmp4 - tmp8 * tmp5;
            double tmp11 = P4.z[k] - P1.z[k];
            double tmp12 = 0.5 * (tmp8 * tmp8 + tmp9 * tmp9 + tmp11 * tmp11);
            double tmp13 = tmp12 * tmp4 - tmp8 * tmp7;
            double tmp14 = tmp12 * tmp5 - tmp9 * tmp7;
            double tmp15 = tmp13 * tmp1 - (tmp14 * tmp0 + tmp3 * tmp10);
            double tmp16 = tmp12 * tmp6 - tmp11 * tmp7;
            double tmp17 = tmp11 * tmp4 - tmp8 * tmp6;
            double tmp18 = tmp16 * tmp0 + tmp3 * tmp17 - tmp13 * tmp2;
            double tmp19 = tmp11 * tmp5 - tmp9 * tmp6;
            double tmp20 = tmp1 * tmp17 - (tmp19 * tmp0 + tmp2 * tmp10);
            double tmp21 = tmp18 + tmp20 * P1.y[k];
            E2[k] = tmp21;
            double tmp22 = tmp20 * P1.z[k] + tmp15;
            E3[k] = tmp22;
            No[k] = tmp20;
            double tmp23 = tmp19 * tmp3 + tmp16 * tmp1 - tmp14 * tmp2;
            double tmp24 = tmp20 * P1.x[k] - tmp23;
            E1[k] = tmp24;
            Ni[k] = 0.5 * (P1.x[k] * (tmp24 - tmp23) + P1.y[k] * (tmp18 + tmp21) + P1.z[k] * (tmp22 + tmp15));
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns P1 = new(i, 0);
        Vec3Columns P2 = new(i, 3);
        Vec3Columns P3 = new(i, 6);
        Vec3Columns P4 = new(i, 9);
        var No = o[0];
        var E1 = o[1];
        var E2 = o[2];
        var E3 = o[3];
        var Ni = o[4];
        #region GMac : SphereThroughPoints
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "ConformalPoint3D", "P1[k]");
        //GMac.Bind("p2", "ConformalPoint3D", "P2[k]");
        //GMac.Bind("p3", "ConformalPoint3D", "P3[k]");
        //GMac.Bind("p4", "ConformalPoint3D", "P4[k]");
        //GMac.Bind("omega.no", "<No[k]>");
        //GMac.Bind("omega.e1", "<E1[k]>");
        //GMac.Bind("omega.e2", "<E2[k]>");
        //GMac.Bind("omega.e3", "<E3[k]>");
        //GMac.Bind("omega.ni", "<Ni[k]>");
        int count0 = P1.x.Length;
        if (P1.y.Length != count0 || P1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || P3.x.Length != count0 || P3.y.Length != count0 || P3.z.Length != count0 || P4.x.Length != count0 || P4.y.Length != count0 || P4.z.Length != count0 || E2.Length != count0 || E3.Length != count0 || No.Length != count0 || E1.Length != count0 || Ni.Length != count0) throw new global::System.ArgumentException("SphereThroughPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, P2.x, P2.y, P2.z, P3.x, P3.y, P3.z, P4.x, P4.y, P4.z, E2, E3, No, E1, Ni");
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
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E2);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E3);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)No);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E1);
        ref double span16 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Ni);
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
            var tmp3 = tmpC0 * (tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2);
            var tmp4 = item6 - item0;
            var tmp5 = item7 - item1;
            var tmp6 = item8 - item2;
            var tmp7 = tmpC0 * (tmp4 * tmp4 + tmp5 * tmp5 + tmp6 * tmp6);
            var tmp8 = item9 - item0;
            var tmp9 = item10 - item1;
            var tmp10 = tmp9 * tmp4 - tmp8 * tmp5;
            var tmp11 = item11 - item2;
            var tmp12 = tmpC0 * (tmp8 * tmp8 + tmp9 * tmp9 + tmp11 * tmp11);
            var tmp13 = tmp12 * tmp4 - tmp8 * tmp7;
            var tmp14 = tmp12 * tmp5 - tmp9 * tmp7;
            var tmp15 = tmp13 * tmp1 - (tmp14 * tmp0 + tmp3 * tmp10);
            var tmp16 = tmp12 * tmp6 - tmp11 * tmp7;
            var tmp17 = tmp11 * tmp4 - tmp8 * tmp6;
            var tmp18 = tmp16 * tmp0 + tmp3 * tmp17 - tmp13 * tmp2;
            var tmp19 = tmp11 * tmp5 - tmp9 * tmp6;
            var tmp20 = tmp1 * tmp17 - (tmp19 * tmp0 + tmp2 * tmp10);
            var tmp21 = tmp18 + tmp20 * item1;
            var result0 = tmp21;
            var tmp22 = tmp20 * item2 + tmp15;
            var result1 = tmp22;
            var result2 = tmp20;
            var tmp23 = tmp19 * tmp3 + tmp16 * tmp1 - tmp14 * tmp2;
            var tmp24 = tmp20 * item0 - tmp23;
            var result3 = tmp24;
            var result4 = tmpC0 * (item0 * (tmp24 - tmp23) + item1 * (tmp18 + tmp21) + item2 * (tmp22 + tmp15));
            Vector512.StoreUnsafe(result0, ref span12, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span13, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span14, (nuint)k);
            Vector512.StoreUnsafe(result3, ref span15, (nuint)k);
            Vector512.StoreUnsafe(result4, ref span16, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P2.x[k] - P1.x[k];
            double tmp1 = P2.y[k] - P1.y[k];
            double tmp2 = P2.z[k] - P1.z[k];
            double tmp3 = 0.5 * (tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2);
            double tmp4 = P3.x[k] - P1.x[k];
            double tmp5 = P3.y[k] - P1.y[k];
            double tmp6 = P3.z[k] - P1.z[k];
            double tmp7 = 0.5 * (tmp4 * tmp4 + tmp5 * tmp5 + tmp6 * tmp6);
            double tmp8 = P4.x[k] - P1.x[k];
            double tmp9 = P4.y[k] - P1.y[k];
            double tmp10 = tmp9 * tmp4 - tmp8 * tmp5;
            double tmp11 = P4.z[k] - P1.z[k];
            double tmp12 = 0.5 * (tmp8 * tmp8 + tmp9 * tmp9 + tmp11 * tmp11);
            double tmp13 = tmp12 * tmp4 - tmp8 * tmp7;
            double tmp14 = tmp12 * tmp5 - tmp9 * tmp7;
            double tmp15 = tmp13 * tmp1 - (tmp14 * tmp0 + tmp3 * tmp10);
            double tmp16 = tmp12 * tmp6 - tmp11 * tmp7;
            double tmp17 = tmp11 * tmp4 - tmp8 * tmp6;
            double tmp18 = tmp16 * tmp0 + tmp3 * tmp17 - tmp13 * tmp2;
            double tmp19 = tmp11 * tmp5 - tmp9 * tmp6;
            double tmp20 = tmp1 * tmp17 - (tmp19 * tmp0 + tmp2 * tmp10);
            double tmp21 = tmp18 + tmp20 * P1.y[k];
            E2[k] = tmp21;
            double tmp22 = tmp20 * P1.z[k] + tmp15;
            E3[k] = tmp22;
            No[k] = tmp20;
            double tmp23 = tmp19 * tmp3 + tmp16 * tmp1 - tmp14 * tmp2;
            double tmp24 = tmp20 * P1.x[k] - tmp23;
            E1[k] = tmp24;
            Ni[k] = 0.5 * (P1.x[k] * (tmp24 - tmp23) + P1.y[k] * (tmp18 + tmp21) + P1.z[k] * (tmp22 + tmp15));
        }
        #endregion
    }
}
