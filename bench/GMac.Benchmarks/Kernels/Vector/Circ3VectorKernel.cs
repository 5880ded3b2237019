using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>Circ3 over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class Circ3VectorKernel() : VectorKernel(new Circ3Kernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns V = new(o, 0);
        #region GMac : Circ3
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("p", "Vector3D", "P[k]");
        //GMac.Bind("v.e1", "<V[k].x>");
        //GMac.Bind("v.e2", "<V[k].y>");
        //GMac.Bind("v.e3", "<V[k].z>");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0) throw new global::System.ArgumentException("Circ3: the spans of a batch must have one length, that of P.x: P.y, P.z, V.x, V.y, V.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.z);
        var tmpC0 = Vector256.Create(4.0);
        var tmpC1 = Vector256.Create(1.0);
        var tmpC2 = Vector256.Create(2.0);
        int k = 0;
        for (; k <= count0 - Vector256<double>.Count; k += Vector256<double>.Count)
        {
            var item0 = Vector256.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector256.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector256.LoadUnsafe(ref span2, (nuint)k);
            var tmp0 = tmpC0 * (item1 * item1 + item0 * item0 - tmpC1);
            var result0 = item0 * tmp0;
            var result1 = item1 * tmp0;
            var result2 = tmpC2 * item2;
            Vector256.StoreUnsafe(result0, ref span3, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span4, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span5, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = 4.0 * (P.y[k] * P.y[k] + P.x[k] * P.x[k] - 1.0);
            V.x[k] = P.x[k] * tmp0;
            V.y[k] = P.y[k] * tmp0;
            V.z[k] = 2.0 * P.z[k];
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns P = new(i, 0);
        Vec3Columns V = new(o, 0);
        #region GMac : Circ3
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("p", "Vector3D", "P[k]");
        //GMac.Bind("v.e1", "<V[k].x>");
        //GMac.Bind("v.e2", "<V[k].y>");
        //GMac.Bind("v.e3", "<V[k].z>");
        int count0 = P.x.Length;
        if (P.y.Length != count0 || P.z.Length != count0 || V.x.Length != count0 || V.y.Length != count0 || V.z.Length != count0) throw new global::System.ArgumentException("Circ3: the spans of a batch must have one length, that of P.x: P.y, P.z, V.x, V.y, V.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)P.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)V.z);
        var tmpC0 = Vector512.Create(4.0);
        var tmpC1 = Vector512.Create(1.0);
        var tmpC2 = Vector512.Create(2.0);
        int k = 0;
        for (; k <= count0 - Vector512<double>.Count; k += Vector512<double>.Count)
        {
            var item0 = Vector512.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector512.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector512.LoadUnsafe(ref span2, (nuint)k);
            var tmp0 = tmpC0 * (item1 * item1 + item0 * item0 - tmpC1);
            var result0 = item0 * tmp0;
            var result1 = item1 * tmp0;
            var result2 = tmpC2 * item2;
            Vector512.StoreUnsafe(result0, ref span3, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span4, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span5, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = 4.0 * (P.y[k] * P.y[k] + P.x[k] * P.x[k] - 1.0);
            V.x[k] = P.x[k] * tmp0;
            V.y[k] = P.y[k] * tmp0;
            V.z[k] = 2.0 * P.z[k];
        }
        #endregion
    }
}
