using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>RotorInterpolate over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed class RotorInterpolateVectorKernel() : VectorKernel(new RotorInterpolateKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Rotor3Columns R1 = new(i, 0);
        Rotor3Columns R2 = new(i, 4);
        var Alpha = i[8];
        Rotor3Columns R = new(o, 0);
        #region GMac : RotorInterpolate
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("r1.1", "<R1[k].w>");
        //GMac.Bind("r1.e2^e3", "<R1[k].x>");
        //GMac.Bind("r1.e3^e1", "<R1[k].y>");
        //GMac.Bind("r1.e1^e2", "<R1[k].z>");
        //GMac.Bind("r2.1", "<R2[k].w>");
        //GMac.Bind("r2.e2^e3", "<R2[k].x>");
        //GMac.Bind("r2.e3^e1", "<R2[k].y>");
        //GMac.Bind("r2.e1^e2", "<R2[k].z>");
        //GMac.Bind("alpha.1", "<Alpha[k]>");
        //GMac.Bind("r.1", "<R[k].w>");
        //GMac.Bind("r.e2^e3", "<R[k].x>");
        //GMac.Bind("r.e3^e1", "<R[k].y>");
        //GMac.Bind("r.e1^e2", "<R[k].z>");
        int count0 = R1.w.Length;
        if (R1.x.Length != count0 || R1.y.Length != count0 || R1.z.Length != count0 || R2.w.Length != count0 || R2.x.Length != count0 || R2.y.Length != count0 || R2.z.Length != count0 || Alpha.Length != count0 || R.w.Length != count0 || R.x.Length != count0 || R.y.Length != count0 || R.z.Length != count0) throw new global::System.ArgumentException("RotorInterpolate: the spans of a batch must have one length, that of R1.w: R1.x, R1.y, R1.z, R2.w, R2.x, R2.y, R2.z, Alpha, R.w, R.x, R.y, R.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.w);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.x);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.y);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.z);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.w);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.x);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.y);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.z);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Alpha);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.w);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.x);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.y);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.z);
        var tmpC0 = Vector256.Create(0.5);
        var tmpC1 = Vector256.Create(1.0);
        var tmpC2 = Vector256.Create(3.479331075960212E-05);
        var tmpC3 = Vector256.Create(0.0007915349942898145);
        var tmpC4 = Vector256.Create(-0.04005553450067941);
        var tmpC5 = Vector256.Create(0.20121253213486293);
        var tmpC6 = Vector256.Create(-0.3255658186224009);
        var tmpC7 = Vector256.Create(0.16666666666666666);
        var tmpC8 = Vector256.Create(0.07703815055590194);
        var tmpC9 = Vector256.Create(-0.6882839716054533);
        var tmpC10 = Vector256.Create(2.0209457602335057);
        var tmpC11 = Vector256.Create(-2.403394911734414);
        var tmpC12 = Vector256.Create(1.5707963267948966);
        var tmpC13 = Vector256.Create(6.123233995736766E-17);
        var tmpC14 = Vector256.Create(3.141592653589793);
        var tmpC15 = Vector256.Create(2.0);
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
            var tmp0 = item0 * item4 + item1 * item5 + item2 * item6 + item3 * item7;
            var tmpL0 = Vector256.Abs(tmp0);
            var tmpL1 = Vector256.LessThanOrEqual(tmpL0, tmpC0);
            var tmpL2 = Vector256.ConditionalSelect(tmpL1, tmp0 * tmp0, (tmpC1 - tmpL0) * tmpC0);
            var tmpL3 = tmpL2 * (tmpC7 + tmpL2 * (tmpC6 + tmpL2 * (tmpC5 + tmpL2 * (tmpC4 + tmpL2 * (tmpC3 + tmpL2 * tmpC2))))) / (tmpC1 + tmpL2 * (tmpC11 + tmpL2 * (tmpC10 + tmpL2 * (tmpC9 + tmpL2 * tmpC8))));
            var tmpL4 = tmpC12 - (tmp0 - (tmpC13 - tmp0 * tmpL3));
            var tmpL5 = Vector256.Sqrt(tmpL2);
            var tmpL6 = tmpC14 - tmpC15 * (tmpL5 + (tmpL3 * tmpL5 - tmpC13));
            var tmpL7 = Vector256.AsDouble(Vector256.AsUInt64(tmpL5) & Vector256.Create(0xFFFFFFFF00000000UL));
            var tmpL8 = tmpL5 + tmpL7;
            var tmpL9 = Vector256.ConditionalSelect(Vector256.Equals(tmpL8, Vector256<double>.Zero), Vector256<double>.Zero, (tmpL2 - tmpL7 * tmpL7) / tmpL8);
            var tmpL10 = tmpC15 * (tmpL7 + (tmpL3 * tmpL5 + tmpL9));
            var tmpL11 = Vector256.ConditionalSelect(tmpL1, tmpL4, Vector256.ConditionalSelect(Vector256.LessThan(tmp0, Vector256<double>.Zero), tmpL6, tmpL10));
            var tmp1 = tmpL11;
            var tmp2 = Vector256.Sin(tmp1);
            var tmp3 = tmp1 * item8;
            var (tmp4, tmp5) = Vector256.SinCos(tmp3);
            var tmp6 = tmp4 / tmp2;
            var tmp7 = tmp5 - tmp0 * tmp6;
            var result0 = item0 * tmp7 + item4 * tmp6;
            var result1 = item1 * tmp7 + item5 * tmp6;
            var result2 = item2 * tmp7 + item6 * tmp6;
            var result3 = item3 * tmp7 + item7 * tmp6;
            Vector256.StoreUnsafe(result0, ref span9, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span10, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span11, (nuint)k);
            Vector256.StoreUnsafe(result3, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = R1.w[k] * R2.w[k] + R1.x[k] * R2.x[k] + R1.y[k] * R2.y[k] + R1.z[k] * R2.z[k];
            double tmp1 = Math.Acos(tmp0);
            double tmp2 = Math.Sin(tmp1);
            double tmp3 = tmp1 * Alpha[k];
            var (tmp4, tmp5) = Math.SinCos(tmp3);
            double tmp6 = tmp4 / tmp2;
            double tmp7 = tmp5 - tmp0 * tmp6;
            R.w[k] = R1.w[k] * tmp7 + R2.w[k] * tmp6;
            R.x[k] = R1.x[k] * tmp7 + R2.x[k] * tmp6;
            R.y[k] = R1.y[k] * tmp7 + R2.y[k] * tmp6;
            R.z[k] = R1.z[k] * tmp7 + R2.z[k] * tmp6;
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Rotor3Columns R1 = new(i, 0);
        Rotor3Columns R2 = new(i, 4);
        var Alpha = i[8];
        Rotor3Columns R = new(o, 0);
        #region GMac : RotorInterpolate
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("r1.1", "<R1[k].w>");
        //GMac.Bind("r1.e2^e3", "<R1[k].x>");
        //GMac.Bind("r1.e3^e1", "<R1[k].y>");
        //GMac.Bind("r1.e1^e2", "<R1[k].z>");
        //GMac.Bind("r2.1", "<R2[k].w>");
        //GMac.Bind("r2.e2^e3", "<R2[k].x>");
        //GMac.Bind("r2.e3^e1", "<R2[k].y>");
        //GMac.Bind("r2.e1^e2", "<R2[k].z>");
        //GMac.Bind("alpha.1", "<Alpha[k]>");
        //GMac.Bind("r.1", "<R[k].w>");
        //GMac.Bind("r.e2^e3", "<R[k].x>");
        //GMac.Bind("r.e3^e1", "<R[k].y>");
        //GMac.Bind("r.e1^e2", "<R[k].z>");
        int count0 = R1.w.Length;
        if (R1.x.Length != count0 || R1.y.Length != count0 || R1.z.Length != count0 || R2.w.Length != count0 || R2.x.Length != count0 || R2.y.Length != count0 || R2.z.Length != count0 || Alpha.Length != count0 || R.w.Length != count0 || R.x.Length != count0 || R.y.Length != count0 || R.z.Length != count0) throw new global::System.ArgumentException("RotorInterpolate: the spans of a batch must have one length, that of R1.w: R1.x, R1.y, R1.z, R2.w, R2.x, R2.y, R2.z, Alpha, R.w, R.x, R.y, R.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.w);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.x);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.y);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R1.z);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.w);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.x);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.y);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)R2.z);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Alpha);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.w);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.x);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.y);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)R.z);
        var tmpC0 = Vector512.Create(0.5);
        var tmpC1 = Vector512.Create(1.0);
        var tmpC2 = Vector512.Create(3.479331075960212E-05);
        var tmpC3 = Vector512.Create(0.0007915349942898145);
        var tmpC4 = Vector512.Create(-0.04005553450067941);
        var tmpC5 = Vector512.Create(0.20121253213486293);
        var tmpC6 = Vector512.Create(-0.3255658186224009);
        var tmpC7 = Vector512.Create(0.16666666666666666);
        var tmpC8 = Vector512.Create(0.07703815055590194);
        var tmpC9 = Vector512.Create(-0.6882839716054533);
        var tmpC10 = Vector512.Create(2.0209457602335057);
        var tmpC11 = Vector512.Create(-2.403394911734414);
        var tmpC12 = Vector512.Create(1.5707963267948966);
        var tmpC13 = Vector512.Create(6.123233995736766E-17);
        var tmpC14 = Vector512.Create(3.141592653589793);
        var tmpC15 = Vector512.Create(2.0);
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
            var tmp0 = item0 * item4 + item1 * item5 + item2 * item6 + item3 * item7;
            var tmpL0 = Vector512.Abs(tmp0);
            var tmpL1 = Vector512.LessThanOrEqual(tmpL0, tmpC0);
            var tmpL2 = Vector512.ConditionalSelect(tmpL1, tmp0 * tmp0, (tmpC1 - tmpL0) * tmpC0);
            var tmpL3 = tmpL2 * (tmpC7 + tmpL2 * (tmpC6 + tmpL2 * (tmpC5 + tmpL2 * (tmpC4 + tmpL2 * (tmpC3 + tmpL2 * tmpC2))))) / (tmpC1 + tmpL2 * (tmpC11 + tmpL2 * (tmpC10 + tmpL2 * (tmpC9 + tmpL2 * tmpC8))));
            var tmpL4 = tmpC12 - (tmp0 - (tmpC13 - tmp0 * tmpL3));
            var tmpL5 = Vector512.Sqrt(tmpL2);
            var tmpL6 = tmpC14 - tmpC15 * (tmpL5 + (tmpL3 * tmpL5 - tmpC13));
            var tmpL7 = Vector512.AsDouble(Vector512.AsUInt64(tmpL5) & Vector512.Create(0xFFFFFFFF00000000UL));
            var tmpL8 = tmpL5 + tmpL7;
            var tmpL9 = Vector512.ConditionalSelect(Vector512.Equals(tmpL8, Vector512<double>.Zero), Vector512<double>.Zero, (tmpL2 - tmpL7 * tmpL7) / tmpL8);
            var tmpL10 = tmpC15 * (tmpL7 + (tmpL3 * tmpL5 + tmpL9));
            var tmpL11 = Vector512.ConditionalSelect(tmpL1, tmpL4, Vector512.ConditionalSelect(Vector512.LessThan(tmp0, Vector512<double>.Zero), tmpL6, tmpL10));
            var tmp1 = tmpL11;
            var tmp2 = Vector512.Sin(tmp1);
            var tmp3 = tmp1 * item8;
            var (tmp4, tmp5) = Vector512.SinCos(tmp3);
            var tmp6 = tmp4 / tmp2;
            var tmp7 = tmp5 - tmp0 * tmp6;
            var result0 = item0 * tmp7 + item4 * tmp6;
            var result1 = item1 * tmp7 + item5 * tmp6;
            var result2 = item2 * tmp7 + item6 * tmp6;
            var result3 = item3 * tmp7 + item7 * tmp6;
            Vector512.StoreUnsafe(result0, ref span9, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span10, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span11, (nuint)k);
            Vector512.StoreUnsafe(result3, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = R1.w[k] * R2.w[k] + R1.x[k] * R2.x[k] + R1.y[k] * R2.y[k] + R1.z[k] * R2.z[k];
            double tmp1 = Math.Acos(tmp0);
            double tmp2 = Math.Sin(tmp1);
            double tmp3 = tmp1 * Alpha[k];
            var (tmp4, tmp5) = Math.SinCos(tmp3);
            double tmp6 = tmp4 / tmp2;
            double tmp7 = tmp5 - tmp0 * tmp6;
            R.w[k] = R1.w[k] * tmp7 + R2.w[k] * tmp6;
            R.x[k] = R1.x[k] * tmp7 + R2.x[k] * tmp6;
            R.y[k] = R1.y[k] * tmp7 + R2.y[k] * tmp6;
            R.z[k] = R1.z[k] * tmp7 + R2.z[k] * tmp6;
        }
        #endregion
    }
}
