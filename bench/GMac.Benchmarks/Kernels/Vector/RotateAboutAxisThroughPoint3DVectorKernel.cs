using System.Runtime.Intrinsics;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>RotateAboutAxisThroughPoint3D over columns: its binding point as a batch in Vector256 and Vector512.</summary>
public sealed partial class RotateAboutAxisThroughPoint3DVectorKernel() : VectorKernel(new RotateAboutAxisThroughPoint3DKernel())
{
    protected override void Generated256(double[][] i, double[][] o)
    {
        Vec3Columns Axis = new(i, 0);
        Vec3Columns Origin = new(i, 3);
        var Angle = i[6];
        Vec3Columns Point = new(i, 7);
        Vec3Columns P = new(o, 0);
        #region GMac : RotateAboutAxisThroughPoint3D
        //GMac.Type("Vector256<double>");
        //GMac.Batch("k");
        //GMac.Bind("axis", "Vector3D", "Axis[k]");
        //GMac.Bind("origin", "Vector3D", "Origin[k]");
        //GMac.Bind("angle.1", "<Angle[k]>");
        //GMac.Bind("x", "Point3D", "Point[k]");
        //GMac.Bind("y", "Point3D", "P[k]");
        int count0 = Axis.x.Length;
        if (Axis.y.Length != count0 || Axis.z.Length != count0 || Origin.x.Length != count0 || Origin.y.Length != count0 || Origin.z.Length != count0 || Angle.Length != count0 || Point.x.Length != count0 || Point.y.Length != count0 || Point.z.Length != count0 || P.x.Length != count0 || P.y.Length != count0 || P.z.Length != count0) throw new global::System.ArgumentException("RotateAboutAxisThroughPoint3D: the spans of a batch must have one length, that of Axis.x: Axis.y, Axis.z, Origin.x, Origin.y, Origin.z, Angle, Point.x, Point.y, Point.z, P.x, P.y, P.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Axis.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Axis.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Axis.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Origin.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Origin.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Origin.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Angle);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Point.x);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Point.y);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Point.z);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)P.x);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)P.y);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)P.z);
        var tmpC0 = Vector256.Create(1.0);
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
            var item9 = Vector256.LoadUnsafe(ref span9, (nuint)k);
            var tmp0 = item2 * item2 + item1 * item1 + item0 * item0;
            var tmp1 = tmpC0 / tmp0;
            var tmp2 = Vector256.Sqrt(tmp1);
            var (tmp4, tmp3) = Vector256.SinCos(item6);
            var tmp5 = tmpC0 - tmp3;
            var tmp6 = item8 - item4;
            var tmp7 = item7 - item3;
            var tmp8 = item9 - item5;
            var tmp9 = tmp2 * tmp6;
            var tmp10 = tmp2 * tmp8;
            var tmp11 = (tmp8 * item2 + item0 * tmp7 + item1 * tmp6) * tmp1;
            var result0 = tmp4 * (item1 * tmp10 - item2 * tmp9) + item7 - tmp5 * (tmp7 - item0 * tmp11);
            var tmp12 = tmp2 * tmp7;
            var result1 = tmp4 * (item2 * tmp12 - item0 * tmp10) + item8 - tmp5 * (tmp6 - item1 * tmp11);
            var result2 = tmp4 * (item0 * tmp9 - item1 * tmp12) + item9 - tmp5 * (tmp8 - item2 * tmp11);
            Vector256.StoreUnsafe(result0, ref span10, (nuint)k);
            Vector256.StoreUnsafe(result1, ref span11, (nuint)k);
            Vector256.StoreUnsafe(result2, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Axis.z[k] * Axis.z[k] + Axis.y[k] * Axis.y[k] + Axis.x[k] * Axis.x[k];
            double tmp1 = 1.0 / tmp0;
            double tmp2 = Math.Sqrt(tmp1);
            var (tmp4, tmp3) = Math.SinCos(Angle[k]);
            double tmp5 = 1.0 - tmp3;
            double tmp6 = Point.y[k] - Origin.y[k];
            double tmp7 = Point.x[k] - Origin.x[k];
            double tmp8 = Point.z[k] - Origin.z[k];
            double tmp9 = tmp2 * tmp6;
            double tmp10 = tmp2 * tmp8;
            double tmp11 = (tmp8 * Axis.z[k] + Axis.x[k] * tmp7 + Axis.y[k] * tmp6) * tmp1;
            P.x[k] = tmp4 * (Axis.y[k] * tmp10 - Axis.z[k] * tmp9) + Point.x[k] - tmp5 * (tmp7 - Axis.x[k] * tmp11);
            double tmp12 = tmp2 * tmp7;
            P.y[k] = tmp4 * (Axis.z[k] * tmp12 - Axis.x[k] * tmp10) + Point.y[k] - tmp5 * (tmp6 - Axis.y[k] * tmp11);
            P.z[k] = tmp4 * (Axis.x[k] * tmp9 - Axis.y[k] * tmp12) + Point.z[k] - tmp5 * (tmp8 - Axis.z[k] * tmp11);
        }
        #endregion
    }

    protected override void Generated512(double[][] i, double[][] o)
    {
        Vec3Columns Axis = new(i, 0);
        Vec3Columns Origin = new(i, 3);
        var Angle = i[6];
        Vec3Columns Point = new(i, 7);
        Vec3Columns P = new(o, 0);
        #region GMac : RotateAboutAxisThroughPoint3D
        //GMac.Type("Vector512<double>");
        //GMac.Batch("k");
        //GMac.Bind("axis", "Vector3D", "Axis[k]");
        //GMac.Bind("origin", "Vector3D", "Origin[k]");
        //GMac.Bind("angle.1", "<Angle[k]>");
        //GMac.Bind("x", "Point3D", "Point[k]");
        //GMac.Bind("y", "Point3D", "P[k]");
        int count0 = Axis.x.Length;
        if (Axis.y.Length != count0 || Axis.z.Length != count0 || Origin.x.Length != count0 || Origin.y.Length != count0 || Origin.z.Length != count0 || Angle.Length != count0 || Point.x.Length != count0 || Point.y.Length != count0 || Point.z.Length != count0 || P.x.Length != count0 || P.y.Length != count0 || P.z.Length != count0) throw new global::System.ArgumentException("RotateAboutAxisThroughPoint3D: the spans of a batch must have one length, that of Axis.x: Axis.y, Axis.z, Origin.x, Origin.y, Origin.z, Angle, Point.x, Point.y, Point.z, P.x, P.y, P.z");
        ref double span0 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Axis.x);
        ref double span1 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Axis.y);
        ref double span2 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Axis.z);
        ref double span3 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Origin.x);
        ref double span4 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Origin.y);
        ref double span5 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Origin.z);
        ref double span6 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Angle);
        ref double span7 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Point.x);
        ref double span8 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Point.y);
        ref double span9 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.ReadOnlySpan<double>)Point.z);
        ref double span10 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)P.x);
        ref double span11 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)P.y);
        ref double span12 = ref global::System.Runtime.InteropServices.MemoryMarshal.GetReference((global::System.Span<double>)P.z);
        var tmpC0 = Vector512.Create(1.0);
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
            var item9 = Vector512.LoadUnsafe(ref span9, (nuint)k);
            var tmp0 = item2 * item2 + item1 * item1 + item0 * item0;
            var tmp1 = tmpC0 / tmp0;
            var tmp2 = Vector512.Sqrt(tmp1);
            var (tmp4, tmp3) = Vector512.SinCos(item6);
            var tmp5 = tmpC0 - tmp3;
            var tmp6 = item8 - item4;
            var tmp7 = item7 - item3;
            var tmp8 = item9 - item5;
            var tmp9 = tmp2 * tmp6;
            var tmp10 = tmp2 * tmp8;
            var tmp11 = (tmp8 * item2 + item0 * tmp7 + item1 * tmp6) * tmp1;
            var result0 = tmp4 * (item1 * tmp10 - item2 * tmp9) + item7 - tmp5 * (tmp7 - item0 * tmp11);
            var tmp12 = tmp2 * tmp7;
            var result1 = tmp4 * (item2 * tmp12 - item0 * tmp10) + item8 - tmp5 * (tmp6 - item1 * tmp11);
            var result2 = tmp4 * (item0 * tmp9 - item1 * tmp12) + item9 - tmp5 * (tmp8 - item2 * tmp11);
            Vector512.StoreUnsafe(result0, ref span10, (nuint)k);
            Vector512.StoreUnsafe(result1, ref span11, (nuint)k);
            Vector512.StoreUnsafe(result2, ref span12, (nuint)k);
        }
        for (; k < count0; k++)
        {
            double tmp0 = Axis.z[k] * Axis.z[k] + Axis.y[k] * Axis.y[k] + Axis.x[k] * Axis.x[k];
            double tmp1 = 1.0 / tmp0;
            double tmp2 = Math.Sqrt(tmp1);
            var (tmp4, tmp3) = Math.SinCos(Angle[k]);
            double tmp5 = 1.0 - tmp3;
            double tmp6 = Point.y[k] - Origin.y[k];
            double tmp7 = Point.x[k] - Origin.x[k];
            double tmp8 = Point.z[k] - Origin.z[k];
            double tmp9 = tmp2 * tmp6;
            double tmp10 = tmp2 * tmp8;
            double tmp11 = (tmp8 * Axis.z[k] + Axis.x[k] * tmp7 + Axis.y[k] * tmp6) * tmp1;
            P.x[k] = tmp4 * (Axis.y[k] * tmp10 - Axis.z[k] * tmp9) + Point.x[k] - tmp5 * (tmp7 - Axis.x[k] * tmp11);
            double tmp12 = tmp2 * tmp7;
            P.y[k] = tmp4 * (Axis.z[k] * tmp12 - Axis.x[k] * tmp10) + Point.y[k] - tmp5 * (tmp6 - Axis.y[k] * tmp11);
            P.z[k] = tmp4 * (Axis.x[k] * tmp9 - Axis.y[k] * tmp12) + Point.z[k] - tmp5 * (tmp8 - Axis.z[k] * tmp11);
        }
        #endregion
    }
}
