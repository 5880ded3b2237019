using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>CircleThroughPoints over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed partial class CircleThroughPointsVectorKernel() : VectorKernel(new CircleThroughPointsKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns Q = new(i, 3);
        Vec3Columns R = new(i, 6);
        double[] c0 = o[0], c1 = o[1], c2 = o[2], c3 = o[3], c4 = o[4], c5 = o[5], c6 = o[6], c7 = o[7], c8 = o[8], c9 = o[9];
        #region GMac : CircleThroughPoints
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "ConformalPoint3D", "P[k]");
        //GMac.Bind("p2", "ConformalPoint3D", "Q[k]");
        //GMac.Bind("p3", "ConformalPoint3D", "R[k]");
        //GMac.Bind("phi.no^e1^e2", "<c0[k]>");
        //GMac.Bind("phi.no^e1^e3", "<c1[k]>");
        //GMac.Bind("phi.no^e2^e3", "<c2[k]>");
        //GMac.Bind("phi.e1^e2^e3", "<c3[k]>");
        //GMac.Bind("phi.no^e1^ni", "<c4[k]>");
        //GMac.Bind("phi.no^e2^ni", "<c5[k]>");
        //GMac.Bind("phi.no^e3^ni", "<c6[k]>");
        //GMac.Bind("phi.e1^e2^ni", "<c7[k]>");
        //GMac.Bind("phi.e1^e3^ni", "<c8[k]>");
        //GMac.Bind("phi.e2^e3^ni", "<c9[k]>");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || Q.x.Length != count0 || Q.y.Length != count0 || Q.z.Length != count0 || R.x.Length != count0 || R.y.Length != count0 || R.z.Length != count0 || c0.Length != count0 || c1.Length != count0 || c2.Length != count0 || c3.Length != count0 || c4.Length != count0 || c5.Length != count0 || c6.Length != count0 || c7.Length != count0 || c8.Length != count0 || c9.Length != count0) throw new global::System.ArgumentException("CircleThroughPoints: the spans of a batch must have one length, that of P.x: P.y, P.z, Q.x, Q.y, Q.z, R.x, R.y, R.z, c0, c1, c2, c3, c4, c5, c6, c7, c8, c9");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c0);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c1);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c2);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c3);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c4);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c5);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c6);
        ref double span16 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c7);
        ref double span17 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c8);
        ref double span18 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c9);
        var tmpC0 = Vector256.Create(-0.5);
        var tmpC1 = Vector256.Create(0.5);
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
            var tmp0 = item0 - item6;
            var tmp1 = item1 - item7;
            var tmp2 = item2 - item8;
            var tmp3 = tmpC0 * (tmp0 * (item0 + item6) + tmp1 * (item1 + item7) + tmp2 * (item2 + item8));
            var tmp4 = item0 - item3;
            var tmp5 = item4 - item1;
            var tmp6 = item5 - item2;
            var tmp7 = tmpC1 * (tmp5 * (item1 + item4) + tmp6 * (item2 + item5) - tmp4 * (item0 + item3));
            var tmp8 = tmp1 * tmp4 + tmp0 * tmp5;
            var tmp9 = tmp2 * tmp4 + tmp0 * tmp6;
            var tmp10 = tmp1 * tmp6 - tmp2 * tmp5;
            var tmp11 = tmp0 * tmp7 - tmp3 * tmp4;
            var tmp12 = tmp1 * tmp7 + tmp3 * tmp5;
            var tmp13 = tmp2 * tmp7 + tmp3 * tmp6;
            var result0 = tmp8;
            var result1 = tmp9;
            var result2 = tmp10;
            var result3 = tmp10 * item0 + tmp8 * item2 - tmp9 * item1;
            var result4 = tmp11;
            var result5 = tmp12;
            var result6 = tmp13;
            var tmp14 = tmpC1 * (item2 * item2 + item1 * item1 + item0 * item0);
            var result7 = tmp8 * tmp14 + tmp12 * item0 - tmp11 * item1;
            var result8 = tmp9 * tmp14 + tmp13 * item0 - tmp11 * item2;
            var result9 = tmp10 * tmp14 + tmp13 * item1 - tmp12 * item2;
            Vector256.StoreUnsafe(result0, ref span9, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span10, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span11, (nuint)k);
            Vector256.StoreUnsafe(result3, ref span12, (nuint)k);
            Vector256.StoreUnsafe(result4, ref span13, (nuint)k);
            Vector256.StoreUnsafe(result5, ref span14, (nuint)k);
            Vector256.StoreUnsafe(result6, ref span15, (nuint)k);
            Vector256.StoreUnsafe(result7, ref span16, (nuint)k);
            Vector256.StoreUnsafe(result8, ref span17, (nuint)k);
            Vector256.StoreUnsafe(result9, ref span18, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P.x[k] - R.x[k];
            double tmp1 = P.y[k] - R.y[k];
            double tmp2 = P.z[k] - R.z[k];
            double tmp3 = -0.5 * (tmp0 * (P.x[k] + R.x[k]) + tmp1 * (P.y[k] + R.y[k]) + tmp2 * (P.z[k] + R.z[k]));
            double tmp4 = P.x[k] - Q.x[k];
            double tmp5 = Q.y[k] - P.y[k];
            double tmp6 = Q.z[k] - P.z[k];
            double tmp7 = 0.5 * (tmp5 * (P.y[k] + Q.y[k]) + tmp6 * (P.z[k] + Q.z[k]) - tmp4 * (P.x[k] + Q.x[k]));
            double tmp8 = tmp1 * tmp4 + tmp0 * tmp5;
            double tmp9 = tmp2 * tmp4 + tmp0 * tmp6;
            double tmp10 = tmp1 * tmp6 - tmp2 * tmp5;
            double tmp11 = tmp0 * tmp7 - tmp3 * tmp4;
            double tmp12 = tmp1 * tmp7 + tmp3 * tmp5;
            double tmp13 = tmp2 * tmp7 + tmp3 * tmp6;
            c0[k] = tmp8;
            c1[k] = tmp9;
            c2[k] = tmp10;
            c3[k] = tmp10 * P.x[k] + tmp8 * P.z[k] - tmp9 * P.y[k];
            c4[k] = tmp11;
            c5[k] = tmp12;
            c6[k] = tmp13;
            double tmp14 = 0.5 * (P.z[k] * P.z[k] + P.y[k] * P.y[k] + P.x[k] * P.x[k]);
            c7[k] = tmp8 * tmp14 + tmp12 * P.x[k] - tmp11 * P.y[k];
            c8[k] = tmp9 * tmp14 + tmp13 * P.x[k] - tmp11 * P.z[k];
            c9[k] = tmp10 * tmp14 + tmp13 * P.y[k] - tmp12 * P.z[k];
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns Q = new(i, 3);
        Vec3Columns R = new(i, 6);
        double[] c0 = o[0], c1 = o[1], c2 = o[2], c3 = o[3], c4 = o[4], c5 = o[5], c6 = o[6], c7 = o[7], c8 = o[8], c9 = o[9];
        #region GMac : CircleThroughPoints
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "ConformalPoint3D", "P[k]");
        //GMac.Bind("p2", "ConformalPoint3D", "Q[k]");
        //GMac.Bind("p3", "ConformalPoint3D", "R[k]");
        //GMac.Bind("phi.no^e1^e2", "<c0[k]>");
        //GMac.Bind("phi.no^e1^e3", "<c1[k]>");
        //GMac.Bind("phi.no^e2^e3", "<c2[k]>");
        //GMac.Bind("phi.e1^e2^e3", "<c3[k]>");
        //GMac.Bind("phi.no^e1^ni", "<c4[k]>");
        //GMac.Bind("phi.no^e2^ni", "<c5[k]>");
        //GMac.Bind("phi.no^e3^ni", "<c6[k]>");
        //GMac.Bind("phi.e1^e2^ni", "<c7[k]>");
        //GMac.Bind("phi.e1^e3^ni", "<c8[k]>");
        //GMac.Bind("phi.e2^e3^ni", "<c9[k]>");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || Q.x.Length != count0 || Q.y.Length != count0 || Q.z.Length != count0 || R.x.Length != count0 || R.y.Length != count0 || R.z.Length != count0 || c0.Length != count0 || c1.Length != count0 || c2.Length != count0 || c3.Length != count0 || c4.Length != count0 || c5.Length != count0 || c6.Length != count0 || c7.Length != count0 || c8.Length != count0 || c9.Length != count0) throw new global::System.ArgumentException("CircleThroughPoints: the spans of a batch must have one length, that of P.x: P.y, P.z, Q.x, Q.y, Q.z, R.x, R.y, R.z, c0, c1, c2, c3, c4, c5, c6, c7, c8, c9");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c0);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c1);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c2);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c3);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c4);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c5);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c6);
        ref double span16 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c7);
        ref double span17 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c8);
        ref double span18 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)c9);
        var tmpC0 = Vector512.Create(-0.5);
        var tmpC1 = Vector512.Create(0.5);
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
            var tmp0 = item0 - item6;
            var tmp1 = item1 - item7;
            var tmp2 = item2 - item8;
            var tmp3 = tmpC0 * (tmp0 * (item0 + item6) + tmp1 * (item1 + item7) + tmp2 * (item2 + item8));
            var tmp4 = item0 - item3;
            var tmp5 = item4 - item1;
            var tmp6 = item5 - item2;
            var tmp7 = tmpC1 * (tmp5 * (item1 + item4) + tmp6 * (item2 + item5) - tmp4 * (item0 + item3));
            var tmp8 = tmp1 * tmp4 + tmp0 * tmp5;
            var tmp9 = tmp2 * tmp4 + tmp0 * tmp6;
            var tmp10 = tmp1 * tmp6 - tmp2 * tmp5;
            var tmp11 = tmp0 * tmp7 - tmp3 * tmp4;
            var tmp12 = tmp1 * tmp7 + tmp3 * tmp5;
            var tmp13 = tmp2 * tmp7 + tmp3 * tmp6;
            var result0 = tmp8;
            var result1 = tmp9;
            var result2 = tmp10;
            var result3 = tmp10 * item0 + tmp8 * item2 - tmp9 * item1;
            var result4 = tmp11;
            var result5 = tmp12;
            var result6 = tmp13;
            var tmp14 = tmpC1 * (item2 * item2 + item1 * item1 + item0 * item0);
            var result7 = tmp8 * tmp14 + tmp12 * item0 - tmp11 * item1;
            var result8 = tmp9 * tmp14 + tmp13 * item0 - tmp11 * item2;
            var result9 = tmp10 * tmp14 + tmp13 * item1 - tmp12 * item2;
            Vector512.StoreUnsafe(result0, ref span9, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span10, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span11, (nuint)k);
            Vector512.StoreUnsafe(result3, ref span12, (nuint)k);
            Vector512.StoreUnsafe(result4, ref span13, (nuint)k);
            Vector512.StoreUnsafe(result5, ref span14, (nuint)k);
            Vector512.StoreUnsafe(result6, ref span15, (nuint)k);
            Vector512.StoreUnsafe(result7, ref span16, (nuint)k);
            Vector512.StoreUnsafe(result8, ref span17, (nuint)k);
            Vector512.StoreUnsafe(result9, ref span18, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = P.x[k] - R.x[k];
            double tmp1 = P.y[k] - R.y[k];
            double tmp2 = P.z[k] - R.z[k];
            double tmp3 = -0.5 * (tmp0 * (P.x[k] + R.x[k]) + tmp1 * (P.y[k] + R.y[k]) + tmp2 * (P.z[k] + R.z[k]));
            double tmp4 = P.x[k] - Q.x[k];
            double tmp5 = Q.y[k] - P.y[k];
            double tmp6 = Q.z[k] - P.z[k];
            double tmp7 = 0.5 * (tmp5 * (P.y[k] + Q.y[k]) + tmp6 * (P.z[k] + Q.z[k]) - tmp4 * (P.x[k] + Q.x[k]));
            double tmp8 = tmp1 * tmp4 + tmp0 * tmp5;
            double tmp9 = tmp2 * tmp4 + tmp0 * tmp6;
            double tmp10 = tmp1 * tmp6 - tmp2 * tmp5;
            double tmp11 = tmp0 * tmp7 - tmp3 * tmp4;
            double tmp12 = tmp1 * tmp7 + tmp3 * tmp5;
            double tmp13 = tmp2 * tmp7 + tmp3 * tmp6;
            c0[k] = tmp8;
            c1[k] = tmp9;
            c2[k] = tmp10;
            c3[k] = tmp10 * P.x[k] + tmp8 * P.z[k] - tmp9 * P.y[k];
            c4[k] = tmp11;
            c5[k] = tmp12;
            c6[k] = tmp13;
            double tmp14 = 0.5 * (P.z[k] * P.z[k] + P.y[k] * P.y[k] + P.x[k] * P.x[k]);
            c7[k] = tmp8 * tmp14 + tmp12 * P.x[k] - tmp11 * P.y[k];
            c8[k] = tmp9 * tmp14 + tmp13 * P.x[k] - tmp11 * P.z[k];
            c9[k] = tmp10 * tmp14 + tmp13 * P.y[k] - tmp12 * P.z[k];
        }
        #endregion
    }
}
