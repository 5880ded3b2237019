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
        if (P1.y.Length != count0 || P1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || P3.x.Length != count0 || P3.y.Length != count0 || P3.z.Length != count0 || P4.x.Length != count0 || P4.y.Length != count0 || P4.z.Length != count0 || No.Length != count0 || E1.Length != count0 || E2.Length != count0 || E3.Length != count0 || Ni.Length != count0) throw new global::System.ArgumentException("SphereThroughPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, P2.x, P2.y, P2.z, P3.x, P3.y, P3.z, P4.x, P4.y, P4.z, No, E1, E2, E3, Ni");
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
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)No);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E1);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E2);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E3);
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
            var tmp0 = item9 - item0;
            var tmp1 = item1 - item10;
            var tmp2 = item2 - item11;
            var tmp3 = tmpC0 * (tmp0 * (item0 + item9) - tmp1 * (item1 + item10) - tmp2 * (item11 + item2));
            var tmp4 = item6 - item0;
            var tmp5 = item1 - item7;
            var tmp6 = item2 - item8;
            var tmp7 = tmpC0 * (tmp4 * (item0 + item6) - tmp5 * (item1 + item7) - tmp6 * (item2 + item8));
            var tmp8 = tmp0 * tmp5 - tmp1 * tmp4;
            var tmp9 = tmp0 * tmp6 - tmp2 * tmp4;
            var tmp10 = tmp2 * tmp5 - tmp1 * tmp6;
            var tmp11 = tmp3 * tmp4 - tmp0 * tmp7;
            var tmp12 = tmp1 * tmp7 - tmp3 * tmp5;
            var tmp13 = tmp2 * tmp7 - tmp3 * tmp6;
            var tmp14 = item0 - item3;
            var tmp15 = item4 - item1;
            var tmp16 = item5 - item2;
            var tmp17 = tmpC0 * (tmp15 * (item1 + item4) + tmp16 * (item2 + item5) - tmp14 * (item0 + item3));
            var tmp18 = tmp15 * tmp9 - (tmp16 * tmp8 - tmp10 * tmp14);
            var tmp19 = tmp17 * tmp8 - tmp11 * tmp15 - tmp12 * tmp14;
            var tmp20 = tmp17 * tmp9 - tmp11 * tmp16 - tmp13 * tmp14;
            var tmp21 = tmp10 * tmp17 + tmp13 * tmp15 - tmp12 * tmp16;
            var result0 = tmp18;
            var result1 = -tmp21;
            var result2 = tmp20;
            var result3 = -tmp19;
            var result4 = tmp20 * item1 - tmpC0 * tmp18 * (item0 * item0 + item1 * item1 + item2 * item2) - tmp19 * item2 - tmp21 * item0;
            Vector256.StoreUnsafe(result0, ref span12, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span13, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span14, (nuint)k);
            Vector256.StoreUnsafe(result3, ref span15, (nuint)k);
            Vector256.StoreUnsafe(result4, ref span16, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P4.x[k] - P1.x[k];
            double tmp1 = P1.y[k] - P4.y[k];
            double tmp2 = P1.z[k] - P4.z[k];
            double tmp3 = 0.5 * (tmp0 * (P1.x[k] + P4.x[k]) - tmp1 * (P1.y[k] + P4.y[k]) - tmp2 * (P4.z[k] + P1.z[k]));
            double tmp4 = P3.x[k] - P1.x[k];
            double tmp5 = P1.y[k] - P3.y[k];
            double tmp6 = P1.z[k] - P3.z[k];
            double tmp7 = 0.5 * (tmp4 * (P1.x[k] + P3.x[k]) - tmp5 * (P1.y[k] + P3.y[k]) - tmp6 * (P1.z[k] + P3.z[k]));
            double tmp8 = tmp0 * tmp5 - tmp1 * tmp4;
            double tmp9 = tmp0 * tmp6 - tmp2 * tmp4;
            double tmp10 = tmp2 * tmp5 - tmp1 * tmp6;
            double tmp11 = tmp3 * tmp4 - tmp0 * tmp7;
            double tmp12 = tmp1 * tmp7 - tmp3 * tmp5;
            double tmp13 = tmp2 * tmp7 - tmp3 * tmp6;
            double tmp14 = P1.x[k] - P2.x[k];
            double tmp15 = P2.y[k] - P1.y[k];
            double tmp16 = P2.z[k] - P1.z[k];
            double tmp17 = 0.5 * (tmp15 * (P1.y[k] + P2.y[k]) + tmp16 * (P1.z[k] + P2.z[k]) - tmp14 * (P1.x[k] + P2.x[k]));
            double tmp18 = tmp15 * tmp9 - (tmp16 * tmp8 - tmp10 * tmp14);
            double tmp19 = tmp17 * tmp8 - tmp11 * tmp15 - tmp12 * tmp14;
            double tmp20 = tmp17 * tmp9 - tmp11 * tmp16 - tmp13 * tmp14;
            double tmp21 = tmp10 * tmp17 + tmp13 * tmp15 - tmp12 * tmp16;
            No[k] = tmp18;
            E1[k] = -tmp21;
            E2[k] = tmp20;
            E3[k] = -tmp19;
            Ni[k] = tmp20 * P1.y[k] - 0.5 * tmp18 * (P1.x[k] * P1.x[k] + P1.y[k] * P1.y[k] + P1.z[k] * P1.z[k]) - tmp19 * P1.z[k] - tmp21 * P1.x[k];
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
        if (P1.y.Length != count0 || P1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || P3.x.Length != count0 || P3.y.Length != count0 || P3.z.Length != count0 || P4.x.Length != count0 || P4.y.Length != count0 || P4.z.Length != count0 || No.Length != count0 || E1.Length != count0 || E2.Length != count0 || E3.Length != count0 || Ni.Length != count0) throw new global::System.ArgumentException("SphereThroughPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, P2.x, P2.y, P2.z, P3.x, P3.y, P3.z, P4.x, P4.y, P4.z, No, E1, E2, E3, Ni");
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
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)No);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E1);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E2);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)E3);
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
            var tmp0 = item9 - item0;
            var tmp1 = item1 - item10;
            var tmp2 = item2 - item11;
            var tmp3 = tmpC0 * (tmp0 * (item0 + item9) - tmp1 * (item1 + item10) - tmp2 * (item11 + item2));
            var tmp4 = item6 - item0;
            var tmp5 = item1 - item7;
            var tmp6 = item2 - item8;
            var tmp7 = tmpC0 * (tmp4 * (item0 + item6) - tmp5 * (item1 + item7) - tmp6 * (item2 + item8));
            var tmp8 = tmp0 * tmp5 - tmp1 * tmp4;
            var tmp9 = tmp0 * tmp6 - tmp2 * tmp4;
            var tmp10 = tmp2 * tmp5 - tmp1 * tmp6;
            var tmp11 = tmp3 * tmp4 - tmp0 * tmp7;
            var tmp12 = tmp1 * tmp7 - tmp3 * tmp5;
            var tmp13 = tmp2 * tmp7 - tmp3 * tmp6;
            var tmp14 = item0 - item3;
            var tmp15 = item4 - item1;
            var tmp16 = item5 - item2;
            var tmp17 = tmpC0 * (tmp15 * (item1 + item4) + tmp16 * (item2 + item5) - tmp14 * (item0 + item3));
            var tmp18 = tmp15 * tmp9 - (tmp16 * tmp8 - tmp10 * tmp14);
            var tmp19 = tmp17 * tmp8 - tmp11 * tmp15 - tmp12 * tmp14;
            var tmp20 = tmp17 * tmp9 - tmp11 * tmp16 - tmp13 * tmp14;
            var tmp21 = tmp10 * tmp17 + tmp13 * tmp15 - tmp12 * tmp16;
            var result0 = tmp18;
            var result1 = -tmp21;
            var result2 = tmp20;
            var result3 = -tmp19;
            var result4 = tmp20 * item1 - tmpC0 * tmp18 * (item0 * item0 + item1 * item1 + item2 * item2) - tmp19 * item2 - tmp21 * item0;
            Vector512.StoreUnsafe(result0, ref span12, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span13, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span14, (nuint)k);
            Vector512.StoreUnsafe(result3, ref span15, (nuint)k);
            Vector512.StoreUnsafe(result4, ref span16, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P4.x[k] - P1.x[k];
            double tmp1 = P1.y[k] - P4.y[k];
            double tmp2 = P1.z[k] - P4.z[k];
            double tmp3 = 0.5 * (tmp0 * (P1.x[k] + P4.x[k]) - tmp1 * (P1.y[k] + P4.y[k]) - tmp2 * (P4.z[k] + P1.z[k]));
            double tmp4 = P3.x[k] - P1.x[k];
            double tmp5 = P1.y[k] - P3.y[k];
            double tmp6 = P1.z[k] - P3.z[k];
            double tmp7 = 0.5 * (tmp4 * (P1.x[k] + P3.x[k]) - tmp5 * (P1.y[k] + P3.y[k]) - tmp6 * (P1.z[k] + P3.z[k]));
            double tmp8 = tmp0 * tmp5 - tmp1 * tmp4;
            double tmp9 = tmp0 * tmp6 - tmp2 * tmp4;
            double tmp10 = tmp2 * tmp5 - tmp1 * tmp6;
            double tmp11 = tmp3 * tmp4 - tmp0 * tmp7;
            double tmp12 = tmp1 * tmp7 - tmp3 * tmp5;
            double tmp13 = tmp2 * tmp7 - tmp3 * tmp6;
            double tmp14 = P1.x[k] - P2.x[k];
            double tmp15 = P2.y[k] - P1.y[k];
            double tmp16 = P2.z[k] - P1.z[k];
            double tmp17 = 0.5 * (tmp15 * (P1.y[k] + P2.y[k]) + tmp16 * (P1.z[k] + P2.z[k]) - tmp14 * (P1.x[k] + P2.x[k]));
            double tmp18 = tmp15 * tmp9 - (tmp16 * tmp8 - tmp10 * tmp14);
            double tmp19 = tmp17 * tmp8 - tmp11 * tmp15 - tmp12 * tmp14;
            double tmp20 = tmp17 * tmp9 - tmp11 * tmp16 - tmp13 * tmp14;
            double tmp21 = tmp10 * tmp17 + tmp13 * tmp15 - tmp12 * tmp16;
            No[k] = tmp18;
            E1[k] = -tmp21;
            E2[k] = tmp20;
            E3[k] = -tmp19;
            Ni[k] = tmp20 * P1.y[k] - 0.5 * tmp18 * (P1.x[k] * P1.x[k] + P1.y[k] * P1.y[k] + P1.z[k] * P1.z[k]) - tmp19 * P1.z[k] - tmp21 * P1.x[k];
        }
        #endregion
    }
}
