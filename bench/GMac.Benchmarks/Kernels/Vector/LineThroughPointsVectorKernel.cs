using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>LineThroughPoints over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed partial class LineThroughPointsVectorKernel() : VectorKernel(new LineThroughPointsKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns Q = new(i, 3);
        double[] dx = o[0], dy = o[1], dz = o[2], m12 = o[3], m13 = o[4], m23 = o[5];
        #region GMac : LineThroughPoints
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "ConformalPoint3D", "P[k]");
        //GMac.Bind("p2", "ConformalPoint3D", "Q[k]");
        //GMac.Bind("line.no^e1^ni", "<dx[k]>");
        //GMac.Bind("line.no^e2^ni", "<dy[k]>");
        //GMac.Bind("line.no^e3^ni", "<dz[k]>");
        //GMac.Bind("line.e1^e2^ni", "<m12[k]>");
        //GMac.Bind("line.e1^e3^ni", "<m13[k]>");
        //GMac.Bind("line.e2^e3^ni", "<m23[k]>");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || Q.x.Length != count0 || Q.y.Length != count0 || Q.z.Length != count0 || dx.Length != count0 || dy.Length != count0 || dz.Length != count0 || m12.Length != count0 || m13.Length != count0 || m23.Length != count0) throw new global::System.ArgumentException("LineThroughPoints: the spans of a batch must have one length, that of P.x: P.y, P.z, Q.x, Q.y, Q.z, dx, dy, dz, m12, m13, m23");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)dx);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)dy);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)dz);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)m12);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)m13);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)m23);
        int k = 0;
        for (; k <= count0 - Vector256<double>.Count; k += Vector256<double>.Count)
        {
            var item0 = Vector256.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector256.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector256.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector256.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector256.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector256.LoadUnsafe(ref span5, (nuint)k);
            var tmp0 = item3 - item0;
            var result0 = tmp0;
            var tmp1 = item4 - item1;
            var result1 = tmp1;
            var tmp2 = item5 - item2;
            var result2 = tmp2;
            var result3 = tmp1 * item0 - tmp0 * item1;
            var result4 = tmp2 * item0 - tmp0 * item2;
            var result5 = tmp2 * item1 - tmp1 * item2;
            Vector256.StoreUnsafe(result0, ref span6, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span7, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span8, (nuint)k);
            Vector256.StoreUnsafe(result3, ref span9, (nuint)k);
            Vector256.StoreUnsafe(result4, ref span10, (nuint)k);
            Vector256.StoreUnsafe(result5, ref span11, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Q.x[k] - P.x[k];
            dx[k] = tmp0;
            double tmp1 = Q.y[k] - P.y[k];
            dy[k] = tmp1;
            double tmp2 = Q.z[k] - P.z[k];
            dz[k] = tmp2;
            m12[k] = tmp1 * P.x[k] - tmp0 * P.y[k];
            m13[k] = tmp2 * P.x[k] - tmp0 * P.z[k];
            m23[k] = tmp2 * P.y[k] - tmp1 * P.z[k];
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns Q = new(i, 3);
        double[] dx = o[0], dy = o[1], dz = o[2], m12 = o[3], m13 = o[4], m23 = o[5];
        #region GMac : LineThroughPoints
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p1", "ConformalPoint3D", "P[k]");
        //GMac.Bind("p2", "ConformalPoint3D", "Q[k]");
        //GMac.Bind("line.no^e1^ni", "<dx[k]>");
        //GMac.Bind("line.no^e2^ni", "<dy[k]>");
        //GMac.Bind("line.no^e3^ni", "<dz[k]>");
        //GMac.Bind("line.e1^e2^ni", "<m12[k]>");
        //GMac.Bind("line.e1^e3^ni", "<m13[k]>");
        //GMac.Bind("line.e2^e3^ni", "<m23[k]>");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || Q.x.Length != count0 || Q.y.Length != count0 || Q.z.Length != count0 || dx.Length != count0 || dy.Length != count0 || dz.Length != count0 || m12.Length != count0 || m13.Length != count0 || m23.Length != count0) throw new global::System.ArgumentException("LineThroughPoints: the spans of a batch must have one length, that of P.x: P.y, P.z, Q.x, Q.y, Q.z, dx, dy, dz, m12, m13, m23");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)dx);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)dy);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)dz);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)m12);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)m13);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)m23);
        int k = 0;
        for (; k <= count0 - Vector512<double>.Count; k += Vector512<double>.Count)
        {
            var item0 = Vector512.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector512.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector512.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector512.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector512.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector512.LoadUnsafe(ref span5, (nuint)k);
            var tmp0 = item3 - item0;
            var result0 = tmp0;
            var tmp1 = item4 - item1;
            var result1 = tmp1;
            var tmp2 = item5 - item2;
            var result2 = tmp2;
            var result3 = tmp1 * item0 - tmp0 * item1;
            var result4 = tmp2 * item0 - tmp0 * item2;
            var result5 = tmp2 * item1 - tmp1 * item2;
            Vector512.StoreUnsafe(result0, ref span6, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span7, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span8, (nuint)k);
            Vector512.StoreUnsafe(result3, ref span9, (nuint)k);
            Vector512.StoreUnsafe(result4, ref span10, (nuint)k);
            Vector512.StoreUnsafe(result5, ref span11, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Q.x[k] - P.x[k];
            dx[k] = tmp0;
            double tmp1 = Q.y[k] - P.y[k];
            dy[k] = tmp1;
            double tmp2 = Q.z[k] - P.z[k];
            dz[k] = tmp2;
            m12[k] = tmp1 * P.x[k] - tmp0 * P.y[k];
            m13[k] = tmp2 * P.x[k] - tmp0 * P.z[k];
            m23[k] = tmp2 * P.y[k] - tmp1 * P.z[k];
        }
        #endregion
    }
}
