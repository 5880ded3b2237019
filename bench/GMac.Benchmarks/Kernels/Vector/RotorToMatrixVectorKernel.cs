using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>RotorToMatrix over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class RotorToMatrixVectorKernel() : VectorKernel(new RotorToMatrixKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Rotor3Columns Q = new(i, 0);
        Vec3Columns MA = new(o, 0);
        Vec3Columns MB = new(o, 3);
        Vec3Columns MC = new(o, 6);
        #region GMac : RotorToMatrix
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("r.1", "<Q[k].w>");
        //GMac.Bind("r.e2^e3", "<Q[k].x>");
        //GMac.Bind("r.e3^e1", "<Q[k].y>");
        //GMac.Bind("r.e1^e2", "<Q[k].z>");
        //GMac.Bind("c1", "Vector3D", "MA[k]");
        //GMac.Bind("c2", "Vector3D", "MB[k]");
        //GMac.Bind("c3", "Vector3D", "MC[k]");
        int count0 = Q.w.Length;
        if (Q.x.Length != count0 || Q.y.Length != count0 || Q.z.Length != count0 || MA.x.Length != count0 || MA.y.Length != count0 || MA.z.Length != count0 || MB.x.Length != count0 || MB.y.Length != count0 || MB.z.Length != count0 || MC.x.Length != count0 || MC.y.Length != count0 || MC.z.Length != count0) throw new global::System.ArgumentException("RotorToMatrix: the spans of a batch must have one length, that of Q.w: Q.x, Q.y, Q.z, MA.x, MA.y, MA.z, MB.x, MB.y, MB.z, MC.x, MC.y, MC.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.w);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.x);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.y);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.z);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MA.x);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MA.y);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MA.z);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MB.x);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MB.y);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MB.z);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MC.x);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MC.y);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MC.z);
        var tmpC0 = Vector256.Create(1.0);
        int k = 0;
        for (; k <= count0 - Vector256<double>.Count; k += Vector256<double>.Count)
        {
            var item0 = Vector256.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector256.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector256.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector256.LoadUnsafe(ref span3, (nuint)k);
            var tmp0 = item1 + item1;
            var tmp1 = item2 + item2;
            var tmp2 = item3 + item3;
            var tmp3 = item3 * tmp2;
            var tmp4 = item2 * tmp1;
            var result0 = tmpC0 - tmp4 - tmp3;
            var tmp5 = item1 * tmp1;
            var tmp6 = item0 * tmp2;
            var result1 = tmp5 - tmp6;
            var tmp7 = item1 * tmp2;
            var tmp8 = item0 * tmp1;
            var result2 = tmp8 + tmp7;
            var result3 = tmp6 + tmp5;
            var tmp9 = item1 * tmp0;
            var result4 = tmpC0 - tmp9 - tmp3;
            var tmp10 = item2 * tmp2;
            var tmp11 = item0 * tmp0;
            var result5 = tmp10 - tmp11;
            var result6 = tmp7 - tmp8;
            var result7 = tmp11 + tmp10;
            var result8 = tmpC0 - tmp9 - tmp4;
            Vector256.StoreUnsafe(result0, ref span4, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span5, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span6, (nuint)k);
            Vector256.StoreUnsafe(result3, ref span7, (nuint)k);
            Vector256.StoreUnsafe(result4, ref span8, (nuint)k);
            Vector256.StoreUnsafe(result5, ref span9, (nuint)k);
            Vector256.StoreUnsafe(result6, ref span10, (nuint)k);
            Vector256.StoreUnsafe(result7, ref span11, (nuint)k);
            Vector256.StoreUnsafe(result8, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Q.x[k] + Q.x[k];
            double tmp1 = Q.y[k] + Q.y[k];
            double tmp2 = Q.z[k] + Q.z[k];
            double tmp3 = Q.z[k] * tmp2;
            double tmp4 = Q.y[k] * tmp1;
            MA.x[k] = 1.0 - tmp4 - tmp3;
            double tmp5 = Q.x[k] * tmp1;
            double tmp6 = Q.w[k] * tmp2;
            MA.y[k] = tmp5 - tmp6;
            double tmp7 = Q.x[k] * tmp2;
            double tmp8 = Q.w[k] * tmp1;
            MA.z[k] = tmp8 + tmp7;
            MB.x[k] = tmp6 + tmp5;
            double tmp9 = Q.x[k] * tmp0;
            MB.y[k] = 1.0 - tmp9 - tmp3;
            double tmp10 = Q.y[k] * tmp2;
            double tmp11 = Q.w[k] * tmp0;
            MB.z[k] = tmp10 - tmp11;
            MC.x[k] = tmp7 - tmp8;
            MC.y[k] = tmp11 + tmp10;
            MC.z[k] = 1.0 - tmp9 - tmp4;
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Rotor3Columns Q = new(i, 0);
        Vec3Columns MA = new(o, 0);
        Vec3Columns MB = new(o, 3);
        Vec3Columns MC = new(o, 6);
        #region GMac : RotorToMatrix
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("r.1", "<Q[k].w>");
        //GMac.Bind("r.e2^e3", "<Q[k].x>");
        //GMac.Bind("r.e3^e1", "<Q[k].y>");
        //GMac.Bind("r.e1^e2", "<Q[k].z>");
        //GMac.Bind("c1", "Vector3D", "MA[k]");
        //GMac.Bind("c2", "Vector3D", "MB[k]");
        //GMac.Bind("c3", "Vector3D", "MC[k]");
        int count0 = Q.w.Length;
        if (Q.x.Length != count0 || Q.y.Length != count0 || Q.z.Length != count0 || MA.x.Length != count0 || MA.y.Length != count0 || MA.z.Length != count0 || MB.x.Length != count0 || MB.y.Length != count0 || MB.z.Length != count0 || MC.x.Length != count0 || MC.y.Length != count0 || MC.z.Length != count0) throw new global::System.ArgumentException("RotorToMatrix: the spans of a batch must have one length, that of Q.w: Q.x, Q.y, Q.z, MA.x, MA.y, MA.z, MB.x, MB.y, MB.z, MC.x, MC.y, MC.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.w);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.x);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.y);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Q.z);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MA.x);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MA.y);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MA.z);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MB.x);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MB.y);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MB.z);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MC.x);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MC.y);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)MC.z);
        var tmpC0 = Vector512.Create(1.0);
        int k = 0;
        for (; k <= count0 - Vector512<double>.Count; k += Vector512<double>.Count)
        {
            var item0 = Vector512.LoadUnsafe(ref span0, (nuint)k);
            var item1 = Vector512.LoadUnsafe(ref span1, (nuint)k);
            var item2 = Vector512.LoadUnsafe(ref span2, (nuint)k);
            var item3 = Vector512.LoadUnsafe(ref span3, (nuint)k);
            var tmp0 = item1 + item1;
            var tmp1 = item2 + item2;
            var tmp2 = item3 + item3;
            var tmp3 = item3 * tmp2;
            var tmp4 = item2 * tmp1;
            var result0 = tmpC0 - tmp4 - tmp3;
            var tmp5 = item1 * tmp1;
            var tmp6 = item0 * tmp2;
            var result1 = tmp5 - tmp6;
            var tmp7 = item1 * tmp2;
            var tmp8 = item0 * tmp1;
            var result2 = tmp8 + tmp7;
            var result3 = tmp6 + tmp5;
            var tmp9 = item1 * tmp0;
            var result4 = tmpC0 - tmp9 - tmp3;
            var tmp10 = item2 * tmp2;
            var tmp11 = item0 * tmp0;
            var result5 = tmp10 - tmp11;
            var result6 = tmp7 - tmp8;
            var result7 = tmp11 + tmp10;
            var result8 = tmpC0 - tmp9 - tmp4;
            Vector512.StoreUnsafe(result0, ref span4, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span5, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span6, (nuint)k);
            Vector512.StoreUnsafe(result3, ref span7, (nuint)k);
            Vector512.StoreUnsafe(result4, ref span8, (nuint)k);
            Vector512.StoreUnsafe(result5, ref span9, (nuint)k);
            Vector512.StoreUnsafe(result6, ref span10, (nuint)k);
            Vector512.StoreUnsafe(result7, ref span11, (nuint)k);
            Vector512.StoreUnsafe(result8, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Q.x[k] + Q.x[k];
            double tmp1 = Q.y[k] + Q.y[k];
            double tmp2 = Q.z[k] + Q.z[k];
            double tmp3 = Q.z[k] * tmp2;
            double tmp4 = Q.y[k] * tmp1;
            MA.x[k] = 1.0 - tmp4 - tmp3;
            double tmp5 = Q.x[k] * tmp1;
            double tmp6 = Q.w[k] * tmp2;
            MA.y[k] = tmp5 - tmp6;
            double tmp7 = Q.x[k] * tmp2;
            double tmp8 = Q.w[k] * tmp1;
            MA.z[k] = tmp8 + tmp7;
            MB.x[k] = tmp6 + tmp5;
            double tmp9 = Q.x[k] * tmp0;
            MB.y[k] = 1.0 - tmp9 - tmp3;
            double tmp10 = Q.y[k] * tmp2;
            double tmp11 = Q.w[k] * tmp0;
            MB.z[k] = tmp10 - tmp11;
            MC.x[k] = tmp7 - tmp8;
            MC.y[k] = tmp11 + tmp10;
            MC.z[k] = 1.0 - tmp9 - tmp4;
        }
        #endregion
    }
}
