using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>SquaredDistance over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed partial class SquaredDistanceVectorKernel() : VectorKernel(new SquaredDistanceKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns U = new(i, 0);
        Vec3Columns V = new(i, 3);
        var D2 = o[0];
        #region GMac : SquaredDistance
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p", "ConformalPoint3D", "U[k]");
        //GMac.Bind("q", "ConformalPoint3D", "V[k]");
        //GMac.Bind("d2.1", "<D2[k]>");
        int count0 = U.x.Length;
        if (U.y.Length != count0 || U.z.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0 || D2.Length != count0) throw new global::System.ArgumentException("SquaredDistance: the spans of a batch must have one length, that of U.x: U.y, U.z, V.x, V.y, V.z, D2");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)D2);
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
            var tmp1 = item4 - item1;
            var tmp2 = item5 - item2;
            var result0 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            Vector256.StoreUnsafe(result0, ref span6, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = V.x[k] - U.x[k];
            double tmp1 = V.y[k] - U.y[k];
            double tmp2 = V.z[k] - U.z[k];
            D2[k] = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns U = new(i, 0);
        Vec3Columns V = new(i, 3);
        var D2 = o[0];
        #region GMac : SquaredDistance
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p", "ConformalPoint3D", "U[k]");
        //GMac.Bind("q", "ConformalPoint3D", "V[k]");
        //GMac.Bind("d2.1", "<D2[k]>");
        int count0 = U.x.Length;
        if (U.y.Length != count0 || U.z.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0 || D2.Length != count0) throw new global::System.ArgumentException("SquaredDistance: the spans of a batch must have one length, that of U.x: U.y, U.z, V.x, V.y, V.z, D2");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)D2);
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
            var tmp1 = item4 - item1;
            var tmp2 = item5 - item2;
            var result0 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
            Vector512.StoreUnsafe(result0, ref span6, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = V.x[k] - U.x[k];
            double tmp1 = V.y[k] - U.y[k];
            double tmp2 = V.z[k] - U.z[k];
            D2[k] = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
        }
        #endregion
    }
}
