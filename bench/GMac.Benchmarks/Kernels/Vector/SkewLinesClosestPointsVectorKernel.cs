using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>SkewLinesClosestPoints over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class SkewLinesClosestPointsVectorKernel() : VectorKernel(new SkewLinesClosestPointsKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns P1 = new(i, 0);
        Vec3Columns D1 = new(i, 3);
        Vec3Columns P2 = new(i, 6);
        Vec3Columns D2 = new(i, 9);
        var T1 = o[0];
        var T2 = o[1];
        #region GMac : SkewLinesClosestPoints
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "Vector3D", "P1[k]");
        //GMac.Bind("d1", "Vector3D", "D1[k]");
        //GMac.Bind("p2", "Vector3D", "P2[k]");
        //GMac.Bind("d2", "Vector3D", "D2[k]");
        //GMac.Bind("t1.1", "<T1[k]>");
        //GMac.Bind("t2.1", "<T2[k]>");
        int count0 = P1.x.Length;
        if (P1.y.Length != count0 || P1.z.Length != count0 || D1.x.Length != count0 || D1.y.Length != count0 || D1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || D2.x.Length != count0 || D2.y.Length != count0 || D2.z.Length != count0 || T1.Length != count0 || T2.Length != count0) throw new global::System.ArgumentException("SkewLinesClosestPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, D1.x, D1.y, D1.z, P2.x, P2.y, P2.z, D2.x, D2.y, D2.z, T1, T2");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D1.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D1.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D1.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D2.x);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D2.y);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D2.z);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)T1);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)T2);
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
            var tmp0 = item10 * item3 - item4 * item9;
            var tmp1 = item11 * item3 - item5 * item9;
            var tmp2 = item11 * item4 - item10 * item5;
            var tmp3 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            var tmp4 = item6 - item0;
            var tmp5 = item7 - item1;
            var tmp6 = item8 - item2;
            var tmp7 = tmp4 * tmp0 - tmp2 * tmp6;
            var tmp8 = tmp6 * tmp1 + tmp5 * tmp0;
            var tmp9 = tmp2 * tmp5 + tmp4 * tmp1;
            var result0 = (item10 * tmp7 + item11 * tmp9 - item9 * tmp8) / tmp3;
            var result1 = (item4 * tmp7 + item5 * tmp9 - item3 * tmp8) / tmp3;
            Vector256.StoreUnsafe(result0, ref span12, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span13, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = D2.y[k] * D1.x[k] - D1.y[k] * D2.x[k];
            double tmp1 = D2.z[k] * D1.x[k] - D1.z[k] * D2.x[k];
            double tmp2 = D2.z[k] * D1.y[k] - D2.y[k] * D1.z[k];
            double tmp3 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            double tmp4 = P2.x[k] - P1.x[k];
            double tmp5 = P2.y[k] - P1.y[k];
            double tmp6 = P2.z[k] - P1.z[k];
            double tmp7 = tmp4 * tmp0 - tmp2 * tmp6;
            double tmp8 = tmp6 * tmp1 + tmp5 * tmp0;
            double tmp9 = tmp2 * tmp5 + tmp4 * tmp1;
            T1[k] = (D2.y[k] * tmp7 + D2.z[k] * tmp9 - D2.x[k] * tmp8) / tmp3;
            T2[k] = (D1.y[k] * tmp7 + D1.z[k] * tmp9 - D1.x[k] * tmp8) / tmp3;
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns P1 = new(i, 0);
        Vec3Columns D1 = new(i, 3);
        Vec3Columns P2 = new(i, 6);
        Vec3Columns D2 = new(i, 9);
        var T1 = o[0];
        var T2 = o[1];
        #region GMac : SkewLinesClosestPoints
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "Vector3D", "P1[k]");
        //GMac.Bind("d1", "Vector3D", "D1[k]");
        //GMac.Bind("p2", "Vector3D", "P2[k]");
        //GMac.Bind("d2", "Vector3D", "D2[k]");
        //GMac.Bind("t1.1", "<T1[k]>");
        //GMac.Bind("t2.1", "<T2[k]>");
        int count0 = P1.x.Length;
        if (P1.y.Length != count0 || P1.z.Length != count0 || D1.x.Length != count0 || D1.y.Length != count0 || D1.z.Length != count0 || P2.x.Length != count0 || P2.y.Length != count0 || P2.z.Length != count0 || D2.x.Length != count0 || D2.y.Length != count0 || D2.z.Length != count0 || T1.Length != count0 || T2.Length != count0) throw new global::System.ArgumentException("SkewLinesClosestPoints: the spans of a batch must have one length, that of P1.x: P1.y, P1.z, D1.x, D1.y, D1.z, P2.x, P2.y, P2.z, D2.x, D2.y, D2.z, T1, T2");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P1.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D1.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D1.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D1.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P2.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D2.x);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D2.y);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)D2.z);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)T1);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)T2);
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
            var tmp0 = item10 * item3 - item4 * item9;
            var tmp1 = item11 * item3 - item5 * item9;
            var tmp2 = item11 * item4 - item10 * item5;
            var tmp3 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            var tmp4 = item6 - item0;
            var tmp5 = item7 - item1;
            var tmp6 = item8 - item2;
            var tmp7 = tmp4 * tmp0 - tmp2 * tmp6;
            var tmp8 = tmp6 * tmp1 + tmp5 * tmp0;
            var tmp9 = tmp2 * tmp5 + tmp4 * tmp1;
            var result0 = (item10 * tmp7 + item11 * tmp9 - item9 * tmp8) / tmp3;
            var result1 = (item4 * tmp7 + item5 * tmp9 - item3 * tmp8) / tmp3;
            Vector512.StoreUnsafe(result0, ref span12, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span13, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = D2.y[k] * D1.x[k] - D1.y[k] * D2.x[k];
            double tmp1 = D2.z[k] * D1.x[k] - D1.z[k] * D2.x[k];
            double tmp2 = D2.z[k] * D1.y[k] - D2.y[k] * D1.z[k];
            double tmp3 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            double tmp4 = P2.x[k] - P1.x[k];
            double tmp5 = P2.y[k] - P1.y[k];
            double tmp6 = P2.z[k] - P1.z[k];
            double tmp7 = tmp4 * tmp0 - tmp2 * tmp6;
            double tmp8 = tmp6 * tmp1 + tmp5 * tmp0;
            double tmp9 = tmp2 * tmp5 + tmp4 * tmp1;
            T1[k] = (D2.y[k] * tmp7 + D2.z[k] * tmp9 - D2.x[k] * tmp8) / tmp3;
            T2[k] = (D1.y[k] * tmp7 + D1.z[k] * tmp9 - D1.x[k] * tmp8) / tmp3;
        }
        #endregion
    }
}
