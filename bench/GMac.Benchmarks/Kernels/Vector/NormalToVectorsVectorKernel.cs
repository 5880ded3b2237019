using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>NormalToVectors over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed partial class NormalToVectorsVectorKernel() : VectorKernel(new NormalToVectorsKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns U = new(i, 0);
        Vec3Columns V = new(i, 3);
        Vec3Columns W = new(o, 0);
        #region GMac : NormalToVectors
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("u", "Vector3D", "U[k]");
        //GMac.Bind("v", "Vector3D", "V[k]");
        //GMac.Bind("w", "Vector3D", "W[k]");
        int count0 = U.x.Length;
        if (U.y.Length != count0 || U.z.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0 || W.x.Length != count0 || W.y.Length != count0 || W.z.Length != count0) throw new global::System.ArgumentException("NormalToVectors: the spans of a batch must have one length, that of U.x: U.y, U.z, V.x, V.y, V.z, W.x, W.y, W.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)W.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)W.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)W.z);
        int k = 0;
        for (; k <= count0 - Vector256<double>.Count; k += Vector256<double>.Count)
        {
            var item0 = Vector256.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector256.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector256.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector256.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector256.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector256.LoadUnsafe(ref span5, (nuint)k);
            var result0 = item1 * item5 - item2 * item4;
            var result1 = item2 * item3 - item0 * item5;
            var result2 = item0 * item4 - item1 * item3;
            Vector256.StoreUnsafe(result0, ref span6, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span7, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span8, (nuint)k);
        }
        for (; k < count0; k++)
        {
            W.x[k] = U.y[k] * V.z[k] - U.z[k] * V.y[k];
            W.y[k] = U.z[k] * V.x[k] - U.x[k] * V.z[k];
            W.z[k] = U.x[k] * V.y[k] - U.y[k] * V.x[k];
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns U = new(i, 0);
        Vec3Columns V = new(i, 3);
        Vec3Columns W = new(o, 0);
        #region GMac : NormalToVectors
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("u", "Vector3D", "U[k]");
        //GMac.Bind("v", "Vector3D", "V[k]");
        //GMac.Bind("w", "Vector3D", "W[k]");
        int count0 = U.x.Length;
        if (U.y.Length != count0 || U.z.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0 || W.x.Length != count0 || W.y.Length != count0 || W.z.Length != count0) throw new global::System.ArgumentException("NormalToVectors: the spans of a batch must have one length, that of U.x: U.y, U.z, V.x, V.y, V.z, W.x, W.y, W.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)U.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)V.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)W.x);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)W.y);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)W.z);
        int k = 0;
        for (; k <= count0 - Vector512<double>.Count; k += Vector512<double>.Count)
        {
            var item0 = Vector512.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector512.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector512.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector512.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector512.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector512.LoadUnsafe(ref span5, (nuint)k);
            var result0 = item1 * item5 - item2 * item4;
            var result1 = item2 * item3 - item0 * item5;
            var result2 = item0 * item4 - item1 * item3;
            Vector512.StoreUnsafe(result0, ref span6, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span7, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span8, (nuint)k);
        }
        for (; k < count0; k++)
        {
            W.x[k] = U.y[k] * V.z[k] - U.z[k] * V.y[k];
            W.y[k] = U.z[k] * V.x[k] - U.x[k] * V.z[k];
            W.z[k] = U.x[k] * V.y[k] - U.y[k] * V.x[k];
        }
        #endregion
    }
}
