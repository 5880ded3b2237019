using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>HiddenSurface over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class HiddenSurfaceVectorKernel() : VectorKernel(new HiddenSurfaceKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec2Columns A = new(i, 0);
        Vec2Columns B = new(i, 2);
        Vec2Columns C = new(i, 4);
        var S = o[0];
        #region GMac : HiddenSurface
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("v1.e1", "<A[k].x>");
        //GMac.Bind("v1.e2", "<A[k].y>");
        //GMac.Bind("v2.e1", "<B[k].x>");
        //GMac.Bind("v2.e2", "<B[k].y>");
        //GMac.Bind("v3.e1", "<C[k].x>");
        //GMac.Bind("v3.e2", "<C[k].y>");
        //GMac.Bind("s.1", "<S[k]>");
        int count0 = A.x.Length;
        if (A.y.Length != count0 || B.x.Length != count0 || B.y.Length != count0 || C.x.Length != count0 || C.y.Length != count0 || S.Length != count0) throw new global::System.ArgumentException("HiddenSurface: the spans of a batch must have one length, that of A.x: A.y, B.x, B.y, C.x, C.y, S");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.x);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.y);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.x);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.y);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)S);
        int k = 0;
        for (; k <= count0 - Vector256<double>.Count; k += Vector256<double>.Count)
        {
            var item0 = Vector256.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector256.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector256.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector256.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector256.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector256.LoadUnsafe(ref span5, (nuint)k);
            var result0 = (item4 - item0) * (item3 - item1) - (item2 - item0) * (item5 - item1);
            Vector256.StoreUnsafe(result0, ref span6, (nuint)k);
        }
        for (; k < count0; k++)
        {
            S[k] = (C.x[k] - A.x[k]) * (B.y[k] - A.y[k]) - (B.x[k] - A.x[k]) * (C.y[k] - A.y[k]);
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec2Columns A = new(i, 0);
        Vec2Columns B = new(i, 2);
        Vec2Columns C = new(i, 4);
        var S = o[0];
        #region GMac : HiddenSurface
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("v1.e1", "<A[k].x>");
        //GMac.Bind("v1.e2", "<A[k].y>");
        //GMac.Bind("v2.e1", "<B[k].x>");
        //GMac.Bind("v2.e2", "<B[k].y>");
        //GMac.Bind("v3.e1", "<C[k].x>");
        //GMac.Bind("v3.e2", "<C[k].y>");
        //GMac.Bind("s.1", "<S[k]>");
        int count0 = A.x.Length;
        if (A.y.Length != count0 || B.x.Length != count0 || B.y.Length != count0 || C.x.Length != count0 || C.y.Length != count0 || S.Length != count0) throw new global::System.ArgumentException("HiddenSurface: the spans of a batch must have one length, that of A.x: A.y, B.x, B.y, C.x, C.y, S");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)A.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.x);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)B.y);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.x);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)C.y);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)S);
        int k = 0;
        for (; k <= count0 - Vector512<double>.Count; k += Vector512<double>.Count)
        {
            var item0 = Vector512.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector512.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector512.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector512.LoadUnsafe(ref span3, (nuint)k);
            var item4 = Vector512.LoadUnsafe(ref span4, (nuint)k);
            var item5 = Vector512.LoadUnsafe(ref span5, (nuint)k);
            var result0 = (item4 - item0) * (item3 - item1) - (item2 - item0) * (item5 - item1);
            Vector512.StoreUnsafe(result0, ref span6, (nuint)k);
        }
        for (; k < count0; k++)
        {
            S[k] = (C.x[k] - A.x[k]) * (B.y[k] - A.y[k]) - (B.x[k] - A.x[k]) * (C.y[k] - A.y[k]);
        }
        #endregion
    }
}
