using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>VortexS over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class VortexSVectorKernel() : VectorKernel(new VortexSKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns A = new(i, 3);
        var Omega = i[6];
        var Gamma = i[7];
        Vec3Columns V = new(o, 0);
        #region GMac : VortexS
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p", "Vector3D", "P[k]");
        //GMac.Bind("a", "Vector3D", "A[k]");
        //GMac.Bind("omega.1", "<Omega[k]>");
        //GMac.Bind("gamma.1", "<Gamma[k]>");
        //GMac.Bind("v", "Vector3D", "V[k]");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || A.x.Length != count0 || A.y.Length != count0 || A.z.Length != count0 || Omega.Length != count0 || Gamma.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0) throw new global::System.ArgumentException("VortexS: the spans of a batch must have one length, that of P.x: P.y, P.z, A.x, A.y, A.z, Omega, Gamma, V.x, V.y, V.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Omega);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Gamma);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.x);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.y);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.z);
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
            var tmp0 = item6 * (item5 * item2 + item4 * item1 + item3 * item0) / (item3 * item3 + item4 * item4 + item5 * item5);
            var result0 = item3 * tmp0 + item7 * (item2 * item4 - item1 * item5);
            var result1 = item4 * tmp0 + item7 * (item0 * item5 - item2 * item3);
            var result2 = item5 * tmp0 + item7 * (item1 * item3 - item0 * item4);
            Vector256.StoreUnsafe(result0, ref span8, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span9, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span10, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Omega[k] * (A.z[k] * P.z[k] + A.y[k] * P.y[k] + A.x[k] * P.x[k]) / (A.x[k] * A.x[k] + A.y[k] * A.y[k] + A.z[k] * A.z[k]);
            V.x[k] = A.x[k] * tmp0 + Gamma[k] * (P.z[k] * A.y[k] - P.y[k] * A.z[k]);
            V.y[k] = A.y[k] * tmp0 + Gamma[k] * (P.x[k] * A.z[k] - P.z[k] * A.x[k]);
            V.z[k] = A.z[k] * tmp0 + Gamma[k] * (P.y[k] * A.x[k] - P.x[k] * A.y[k]);
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns A = new(i, 3);
        var Omega = i[6];
        var Gamma = i[7];
        Vec3Columns V = new(o, 0);
        #region GMac : VortexS
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p", "Vector3D", "P[k]");
        //GMac.Bind("a", "Vector3D", "A[k]");
        //GMac.Bind("omega.1", "<Omega[k]>");
        //GMac.Bind("gamma.1", "<Gamma[k]>");
        //GMac.Bind("v", "Vector3D", "V[k]");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || A.x.Length != count0 || A.y.Length != count0 || A.z.Length != count0 || Omega.Length != count0 || Gamma.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0) throw new global::System.ArgumentException("VortexS: the spans of a batch must have one length, that of P.x: P.y, P.z, A.x, A.y, A.z, Omega, Gamma, V.x, V.y, V.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Omega);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Gamma);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.x);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.y);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.z);
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
            var tmp0 = item6 * (item5 * item2 + item4 * item1 + item3 * item0) / (item3 * item3 + item4 * item4 + item5 * item5);
            var result0 = item3 * tmp0 + item7 * (item2 * item4 - item1 * item5);
            var result1 = item4 * tmp0 + item7 * (item0 * item5 - item2 * item3);
            var result2 = item5 * tmp0 + item7 * (item1 * item3 - item0 * item4);
            Vector512.StoreUnsafe(result0, ref span8, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span9, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span10, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Omega[k] * (A.z[k] * P.z[k] + A.y[k] * P.y[k] + A.x[k] * P.x[k]) / (A.x[k] * A.x[k] + A.y[k] * A.y[k] + A.z[k] * A.z[k]);
            V.x[k] = A.x[k] * tmp0 + Gamma[k] * (P.z[k] * A.y[k] - P.y[k] * A.z[k]);
            V.y[k] = A.y[k] * tmp0 + Gamma[k] * (P.x[k] * A.z[k] - P.z[k] * A.x[k]);
            V.z[k] = A.z[k] * tmp0 + Gamma[k] * (P.y[k] * A.x[k] - P.x[k] * A.y[k]);
        }
        #endregion
    }
}
