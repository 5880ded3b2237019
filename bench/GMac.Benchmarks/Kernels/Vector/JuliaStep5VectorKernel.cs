using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>JuliaStep5 over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class JuliaStep5VectorKernel() : VectorKernel(new JuliaStep5Kernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec2Columns X = new(i, 0);
        Vec2Columns C = new(i, 2);
        Vec2Columns Y = new(o, 0);
        #region GMac : JuliaStep5
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("x.e1", "<X[k].x>");
        //GMac.Bind("x.e2", "<X[k].y>");
        //GMac.Bind("c.e1", "<C[k].x>");
        //GMac.Bind("c.e2", "<C[k].y>");
        //GMac.Bind("y.e1", "<Y[k].x>");
        //GMac.Bind("y.e2", "<Y[k].y>");
        int count0 = X.x.Length;
        if (X.y.Length != count0 || C.x.Length != count0 || C.y.Length != count0 || Y.x.Length != count0 || Y.y.Length != count0) throw new global::System.ArgumentException("JuliaStep5: the spans of a batch must have one length, that of X.x: X.y, C.x, C.y, Y.x, Y.y");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)X.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)X.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.x);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.y);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Y.x);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Y.y);
        var tmpC0 = Vector256.Create(10.0);
        var tmpC1 = Vector256.Create(5.0);
        int k = 0;
        for (; k <= count0 - Vector256<double>.Count; k += Vector256<double>.Count)
        {
            var item0 = Vector256.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector256.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector256.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector256.LoadUnsafe(ref span3, (nuint)k);
            var tmp0 = item1 * item1;
            var tmp1 = tmpC0 * tmp0;
            var tmp2 = item0 * item0;
            var tmp3 = tmp0 * tmp0;
            var result0 = item0 * ((tmp2 - tmp1) * tmp2 + tmpC1 * tmp3) + item2;
            var result1 = item1 * ((tmpC1 * tmp2 - tmp1) * tmp2 + tmp3) + item3;
            Vector256.StoreUnsafe(result0, ref span4, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span5, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = X.y[k] * X.y[k];
            double tmp1 = 10.0 * tmp0;
            double tmp2 = X.x[k] * X.x[k];
            double tmp3 = tmp0 * tmp0;
            Y.x[k] = X.x[k] * ((tmp2 - tmp1) * tmp2 + 5.0 * tmp3) + C.x[k];
            Y.y[k] = X.y[k] * ((5.0 * tmp2 - tmp1) * tmp2 + tmp3) + C.y[k];
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec2Columns X = new(i, 0);
        Vec2Columns C = new(i, 2);
        Vec2Columns Y = new(o, 0);
        #region GMac : JuliaStep5
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("x.e1", "<X[k].x>");
        //GMac.Bind("x.e2", "<X[k].y>");
        //GMac.Bind("c.e1", "<C[k].x>");
        //GMac.Bind("c.e2", "<C[k].y>");
        //GMac.Bind("y.e1", "<Y[k].x>");
        //GMac.Bind("y.e2", "<Y[k].y>");
        int count0 = X.x.Length;
        if (X.y.Length != count0 || C.x.Length != count0 || C.y.Length != count0 || Y.x.Length != count0 || Y.y.Length != count0) throw new global::System.ArgumentException("JuliaStep5: the spans of a batch must have one length, that of X.x: X.y, C.x, C.y, Y.x, Y.y");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)X.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)X.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.x);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.y);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Y.x);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)Y.y);
        var tmpC0 = Vector512.Create(10.0);
        var tmpC1 = Vector512.Create(5.0);
        int k = 0;
        for (; k <= count0 - Vector512<double>.Count; k += Vector512<double>.Count)
        {
            var item0 = Vector512.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector512.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector512.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector512.LoadUnsafe(ref span3, (nuint)k);
            var tmp0 = item1 * item1;
            var tmp1 = tmpC0 * tmp0;
            var tmp2 = item0 * item0;
            var tmp3 = tmp0 * tmp0;
            var result0 = item0 * ((tmp2 - tmp1) * tmp2 + tmpC1 * tmp3) + item2;
            var result1 = item1 * ((tmpC1 * tmp2 - tmp1) * tmp2 + tmp3) + item3;
            Vector512.StoreUnsafe(result0, ref span4, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span5, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = X.y[k] * X.y[k];
            double tmp1 = 10.0 * tmp0;
            double tmp2 = X.x[k] * X.x[k];
            double tmp3 = tmp0 * tmp0;
            Y.x[k] = X.x[k] * ((tmp2 - tmp1) * tmp2 + 5.0 * tmp3) + C.x[k];
            Y.y[k] = X.y[k] * ((5.0 * tmp2 - tmp1) * tmp2 + tmp3) + C.y[k];
        }
        #endregion
    }
}
