using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>GramSchmidtRejection over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class GramSchmidtRejectionVectorKernel() : VectorKernel(new GramSchmidtRejectionKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns A = new(i, 0);
        Vec3Columns B = new(i, 3);
        Vec3Columns C = new(i, 6);
        Vec3Columns WA = new(o, 0);
        Vec3Columns WB = new(o, 3);
        Vec3Columns WC = new(o, 6);
        #region GMac : GramSchmidtRejection
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("v1", "Vector3D", "A[k]");
        //GMac.Bind("v2", "Vector3D", "B[k]");
        //GMac.Bind("v3", "Vector3D", "C[k]");
        //GMac.Bind("w1", "Vector3D", "WA[k]");
        //GMac.Bind("w2", "Vector3D", "WB[k]");
        //GMac.Bind("w3", "Vector3D", "WC[k]");
        int count0 = A.x.Length;
        if (A.y.Length != count0 || A.z.Length != count0 || B.x.Length != count0 || B.y.Length != count0 || B.z.Length != count0 || C.x.Length != count0 || C.y.Length != count0 || C.z.Length != count0 || WA.x.Length != count0 || WA.y.Length != count0 || WA.z.Length != count0 || WB.x.Length != count0 || WB.y.Length != count0 || WB.z.Length != count0 || WC.x.Length != count0 || WC.y.Length != count0 || WC.z.Length != count0) throw new global::System.ArgumentException("GramSchmidtRejection: the spans of a batch must have one length, that of A.x: A.y, A.z, B.x, B.y, B.z, C.x, C.y, C.z, WA.x, WA.y, WA.z, WB.x, WB.y, WB.z, WC.x, WC.y, WC.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WA.x);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WA.y);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WA.z);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WB.x);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WB.y);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WB.z);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WC.x);
        ref double span16 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WC.y);
        ref double span17 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WC.z);
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
            var tmp0 = item4 - item1;
            var tmp1 = item3 - item0;
            var tmp2 = tmp0 * item0 - tmp1 * item1;
            var tmp3 = item5 - item2;
            var tmp4 = tmp1 * item2 - tmp3 * item0;
            var tmp5 = tmp3 * item1 - tmp0 * item2;
            var tmp6 = (item0 * item3 + item1 * item4 + item2 * item5) / (item2 * item2 + item0 * item0 + item1 * item1);
            var result0 = item0;
            var result1 = item1;
            var result2 = item2;
            var result3 = item3 - item0 * tmp6;
            var result4 = item4 - item1 * tmp6;
            var result5 = item5 - item2 * tmp6;
            var tmp7 = (item7 * tmp4 + item6 * tmp5 + item8 * tmp2) / (tmp2 * tmp2 + tmp4 * tmp4 + tmp5 * tmp5);
            var result6 = tmp5 * tmp7;
            var result7 = tmp4 * tmp7;
            var result8 = tmp2 * tmp7;
            Vector256.StoreUnsafe(result0, ref span9, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span10, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span11, (nuint)k);
            Vector256.StoreUnsafe(result3, ref span12, (nuint)k);
            Vector256.StoreUnsafe(result4, ref span13, (nuint)k);
            Vector256.StoreUnsafe(result5, ref span14, (nuint)k);
            Vector256.StoreUnsafe(result6, ref span15, (nuint)k);
            Vector256.StoreUnsafe(result7, ref span16, (nuint)k);
            Vector256.StoreUnsafe(result8, ref span17, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = B.y[k] - A.y[k];
            double tmp1 = B.x[k] - A.x[k];
            double tmp2 = tmp0 * A.x[k] - tmp1 * A.y[k];
            double tmp3 = B.z[k] - A.z[k];
            double tmp4 = tmp1 * A.z[k] - tmp3 * A.x[k];
            double tmp5 = tmp3 * A.y[k] - tmp0 * A.z[k];
            double tmp6 = (A.x[k] * B.x[k] + A.y[k] * B.y[k] + A.z[k] * B.z[k]) / (A.z[k] * A.z[k] + A.x[k] * A.x[k] + A.y[k] * A.y[k]);
            WA.x[k] = A.x[k];
            WA.y[k] = A.y[k];
            WA.z[k] = A.z[k];
            WB.x[k] = B.x[k] - A.x[k] * tmp6;
            WB.y[k] = B.y[k] - A.y[k] * tmp6;
            WB.z[k] = B.z[k] - A.z[k] * tmp6;
            double tmp7 = (C.y[k] * tmp4 + C.x[k] * tmp5 + C.z[k] * tmp2) / (tmp2 * tmp2 + tmp4 * tmp4 + tmp5 * tmp5);
            WC.x[k] = tmp5 * tmp7;
            WC.y[k] = tmp4 * tmp7;
            WC.z[k] = tmp2 * tmp7;
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns A = new(i, 0);
        Vec3Columns B = new(i, 3);
        Vec3Columns C = new(i, 6);
        Vec3Columns WA = new(o, 0);
        Vec3Columns WB = new(o, 3);
        Vec3Columns WC = new(o, 6);
        #region GMac : GramSchmidtRejection
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("v1", "Vector3D", "A[k]");
        //GMac.Bind("v2", "Vector3D", "B[k]");
        //GMac.Bind("v3", "Vector3D", "C[k]");
        //GMac.Bind("w1", "Vector3D", "WA[k]");
        //GMac.Bind("w2", "Vector3D", "WB[k]");
        //GMac.Bind("w3", "Vector3D", "WC[k]");
        int count0 = A.x.Length;
        if (A.y.Length != count0 || A.z.Length != count0 || B.x.Length != count0 || B.y.Length != count0 || B.z.Length != count0 || C.x.Length != count0 || C.y.Length != count0 || C.z.Length != count0 || WA.x.Length != count0 || WA.y.Length != count0 || WA.z.Length != count0 || WB.x.Length != count0 || WB.y.Length != count0 || WB.z.Length != count0 || WC.x.Length != count0 || WC.y.Length != count0 || WC.z.Length != count0) throw new global::System.ArgumentException("GramSchmidtRejection: the spans of a batch must have one length, that of A.x: A.y, A.z, B.x, B.y, B.z, C.x, C.y, C.z, WA.x, WA.y, WA.z, WB.x, WB.y, WB.z, WC.x, WC.y, WC.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.z);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WA.x);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WA.y);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WA.z);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WB.x);
        ref double span13 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WB.y);
        ref double span14 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WB.z);
        ref double span15 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WC.x);
        ref double span16 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WC.y);
        ref double span17 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)WC.z);
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
            var tmp0 = item4 - item1;
            var tmp1 = item3 - item0;
            var tmp2 = tmp0 * item0 - tmp1 * item1;
            var tmp3 = item5 - item2;
            var tmp4 = tmp1 * item2 - tmp3 * item0;
            var tmp5 = tmp3 * item1 - tmp0 * item2;
            var tmp6 = (item0 * item3 + item1 * item4 + item2 * item5) / (item2 * item2 + item0 * item0 + item1 * item1);
            var result0 = item0;
            var result1 = item1;
            var result2 = item2;
            var result3 = item3 - item0 * tmp6;
            var result4 = item4 - item1 * tmp6;
            var result5 = item5 - item2 * tmp6;
            var tmp7 = (item7 * tmp4 + item6 * tmp5 + item8 * tmp2) / (tmp2 * tmp2 + tmp4 * tmp4 + tmp5 * tmp5);
            var result6 = tmp5 * tmp7;
            var result7 = tmp4 * tmp7;
            var result8 = tmp2 * tmp7;
            Vector512.StoreUnsafe(result0, ref span9, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span10, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span11, (nuint)k);
            Vector512.StoreUnsafe(result3, ref span12, (nuint)k);
            Vector512.StoreUnsafe(result4, ref span13, (nuint)k);
            Vector512.StoreUnsafe(result5, ref span14, (nuint)k);
            Vector512.StoreUnsafe(result6, ref span15, (nuint)k);
            Vector512.StoreUnsafe(result7, ref span16, (nuint)k);
            Vector512.StoreUnsafe(result8, ref span17, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = B.y[k] - A.y[k];
            double tmp1 = B.x[k] - A.x[k];
            double tmp2 = tmp0 * A.x[k] - tmp1 * A.y[k];
            double tmp3 = B.z[k] - A.z[k];
            double tmp4 = tmp1 * A.z[k] - tmp3 * A.x[k];
            double tmp5 = tmp3 * A.y[k] - tmp0 * A.z[k];
            double tmp6 = (A.x[k] * B.x[k] + A.y[k] * B.y[k] + A.z[k] * B.z[k]) / (A.z[k] * A.z[k] + A.x[k] * A.x[k] + A.y[k] * A.y[k]);
            WA.x[k] = A.x[k];
            WA.y[k] = A.y[k];
            WA.z[k] = A.z[k];
            WB.x[k] = B.x[k] - A.x[k] * tmp6;
            WB.y[k] = B.y[k] - A.y[k] * tmp6;
            WB.z[k] = B.z[k] - A.z[k] * tmp6;
            double tmp7 = (C.y[k] * tmp4 + C.x[k] * tmp5 + C.z[k] * tmp2) / (tmp2 * tmp2 + tmp4 * tmp4 + tmp5 * tmp5);
            WC.x[k] = tmp5 * tmp7;
            WC.y[k] = tmp4 * tmp7;
            WC.z[k] = tmp2 * tmp7;
        }
        #endregion
    }
}
