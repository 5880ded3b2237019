using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Transforms;

/// <summary>
/// An invertible affine map of 3D space stored as a 4×4 matrix together with its inverse.
/// The inverse is kept alongside because instancing needs it for every ray; composing two
/// transforms composes both matrices, so no inversion happens after construction.
/// Composition <c>a * b</c> applies <c>b</c> first, then <c>a</c>.
/// </summary>
public sealed class AffineTransform
{
    // Row-major 4×4; the last row of an affine matrix is always (0, 0, 0, 1).
    private readonly double[] _m;
    private readonly double[] _inv;

    private AffineTransform(double[] m, double[] inv)
    {
        _m = m;
        _inv = inv;
    }

    public static AffineTransform Identity { get; } = new(IdentityArray(), IdentityArray());

    /// <summary>Forward matrix element (row, column).</summary>
    public double this[int row, int column] => _m[row * 4 + column];

    public AffineTransform Inverse => new(_inv, _m);

    public static AffineTransform Translation(double dx, double dy, double dz)
    {
        double[] m = IdentityArray(), inv = IdentityArray();
        m[3] = dx;
        m[7] = dy;
        m[11] = dz;
        inv[3] = -dx;
        inv[7] = -dy;
        inv[11] = -dz;
        return new(m, inv);
    }

    public static AffineTransform Translation(Vector3D d) => Translation(d.x, d.y, d.z);

    public static AffineTransform Scaling(double sx, double sy, double sz)
    {
        if (sx == 0 || sy == 0 || sz == 0)
        {
            throw new ArgumentException("A scaling factor of zero is not invertible.");
        }

        double[] m = IdentityArray(), inv = IdentityArray();
        m[0] = sx;
        m[5] = sy;
        m[10] = sz;
        inv[0] = 1 / sx;
        inv[5] = 1 / sy;
        inv[10] = 1 / sz;
        return new(m, inv);
    }

    public static AffineTransform Scaling(double s) => Scaling(s, s, s);

    /// <summary>Rotation about the x axis by <paramref name="radians"/> (right-handed).</summary>
    public static AffineTransform RotationX(double radians)
    {
        double c = Math.Cos(radians), s = Math.Sin(radians);
        double[] m = IdentityArray();
        m[5] = c;
        m[6] = -s;
        m[9] = s;
        m[10] = c;
        return new(m, Transpose3x3(m));
    }

    public static AffineTransform RotationY(double radians)
    {
        double c = Math.Cos(radians), s = Math.Sin(radians);
        double[] m = IdentityArray();
        m[0] = c;
        m[2] = s;
        m[8] = -s;
        m[10] = c;
        return new(m, Transpose3x3(m));
    }

    public static AffineTransform RotationZ(double radians)
    {
        double c = Math.Cos(radians), s = Math.Sin(radians);
        double[] m = IdentityArray();
        m[0] = c;
        m[1] = -s;
        m[4] = s;
        m[5] = c;
        return new(m, Transpose3x3(m));
    }

    /// <summary>Rotation by <paramref name="radians"/> about an arbitrary axis through the origin (Rodrigues).</summary>
    public static AffineTransform Rotation(Vector3D axis, double radians)
    {
        if (axis.LengthSquared == 0)
        {
            throw new ArgumentException("The rotation axis must not be the zero vector.", nameof(axis));
        }

        var a = axis.Normalized();
        double c = Math.Cos(radians), s = Math.Sin(radians), k = 1 - c;
        double[] m = IdentityArray();
        m[0] = c + a.x * a.x * k;
        m[1] = a.x * a.y * k - a.z * s;
        m[2] = a.x * a.z * k + a.y * s;
        m[4] = a.y * a.x * k + a.z * s;
        m[5] = c + a.y * a.y * k;
        m[6] = a.y * a.z * k - a.x * s;
        m[8] = a.z * a.x * k - a.y * s;
        m[9] = a.z * a.y * k + a.x * s;
        m[10] = c + a.z * a.z * k;
        return new(m, Transpose3x3(m));
    }

    /// <summary>
    /// Builds a transform from a general 4×4 row-major matrix whose last row is (0, 0, 0, 1);
    /// the inverse is computed by Gauss–Jordan elimination with partial pivoting.
    /// </summary>
    public static AffineTransform FromMatrix(double[,] matrix)
    {
        ArgumentNullException.ThrowIfNull(matrix);
        if (matrix.GetLength(0) != 4 || matrix.GetLength(1) != 4)
        {
            throw new ArgumentException("An affine transform needs a 4×4 matrix.", nameof(matrix));
        }

        if (matrix[3, 0] != 0 || matrix[3, 1] != 0 || matrix[3, 2] != 0 || matrix[3, 3] != 1)
        {
            throw new ArgumentException("The last row of an affine matrix must be (0, 0, 0, 1).", nameof(matrix));
        }

        var m = new double[16];
        for (int r = 0; r < 4; r++)
        {
            for (int c = 0; c < 4; c++)
            {
                m[r * 4 + c] = matrix[r, c];
            }
        }

        return new(m, Invert(m));
    }

    public static AffineTransform operator *(AffineTransform a, AffineTransform b) =>
        new(Multiply(a._m, b._m), Multiply(b._inv, a._inv));

    /// <summary>This transform followed by <paramref name="next"/>.</summary>
    public AffineTransform Then(AffineTransform next) => next * this;

    public Point3D TransformPoint(Point3D p) => Apply(_m, p);

    public Vector3D TransformVector(Vector3D v) => ApplyLinear(_m, v);

    /// <summary>Normals transform with the inverse transpose so they stay perpendicular to surfaces.</summary>
    public Normal3D TransformNormal(Normal3D n) => new(
        _inv[0] * n.x + _inv[4] * n.y + _inv[8] * n.z,
        _inv[1] * n.x + _inv[5] * n.y + _inv[9] * n.z,
        _inv[2] * n.x + _inv[6] * n.y + _inv[10] * n.z);

    public Point3D InverseTransformPoint(Point3D p) => Apply(_inv, p);

    /// <summary>The ray mapped into the untransformed object's frame (same parameter t on both rays).</summary>
    public Ray InverseTransformRay(in Ray ray) => new(Apply(_inv, ray.o), ApplyLinear(_inv, ray.d), ray.tMin);

    /// <summary>Axis-aligned box enclosing the image of <paramref name="box"/>.</summary>
    public BoundingBox TransformBox(in BoundingBox box) => box.Map(TransformPoint);

    private static Point3D Apply(double[] m, Point3D p) => new(
        m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
        m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
        m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);

    private static Vector3D ApplyLinear(double[] m, Vector3D v) => new(
        m[0] * v.x + m[1] * v.y + m[2] * v.z,
        m[4] * v.x + m[5] * v.y + m[6] * v.z,
        m[8] * v.x + m[9] * v.y + m[10] * v.z);

    private static double[] IdentityArray() => [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];

    // The inverse of a rotation is its transpose.
    private static double[] Transpose3x3(double[] m)
    {
        double[] t = IdentityArray();
        for (int r = 0; r < 3; r++)
        {
            for (int c = 0; c < 3; c++)
            {
                t[r * 4 + c] = m[c * 4 + r];
            }
        }

        return t;
    }

    private static double[] Multiply(double[] a, double[] b)
    {
        var p = new double[16];
        for (int r = 0; r < 4; r++)
        {
            for (int c = 0; c < 4; c++)
            {
                double s = 0;
                for (int k = 0; k < 4; k++)
                {
                    s += a[r * 4 + k] * b[k * 4 + c];
                }

                p[r * 4 + c] = s;
            }
        }

        return p;
    }

    private static double[] Invert(double[] source)
    {
        var a = (double[])source.Clone();
        double[] inv = IdentityArray();
        double scale = 0;
        foreach (double v in a)
        {
            scale = Math.Max(scale, Math.Abs(v));
        }

        for (int col = 0; col < 4; col++)
        {
            int pivot = col;
            for (int r = col + 1; r < 4; r++)
            {
                if (Math.Abs(a[r * 4 + col]) > Math.Abs(a[pivot * 4 + col]))
                {
                    pivot = r;
                }
            }

            if (Math.Abs(a[pivot * 4 + col]) <= 1e-14 * scale)
            {
                throw new ArgumentException("The matrix is singular and has no inverse.");
            }

            if (pivot != col)
            {
                for (int c = 0; c < 4; c++)
                {
                    (a[col * 4 + c], a[pivot * 4 + c]) = (a[pivot * 4 + c], a[col * 4 + c]);
                    (inv[col * 4 + c], inv[pivot * 4 + c]) = (inv[pivot * 4 + c], inv[col * 4 + c]);
                }
            }

            double d = 1.0 / a[col * 4 + col];
            for (int c = 0; c < 4; c++)
            {
                a[col * 4 + c] *= d;
                inv[col * 4 + c] *= d;
            }

            for (int r = 0; r < 4; r++)
            {
                if (r == col)
                {
                    continue;
                }

                double f = a[r * 4 + col];
                if (f == 0)
                {
                    continue;
                }

                for (int c = 0; c < 4; c++)
                {
                    a[r * 4 + c] -= f * a[col * 4 + c];
                    inv[r * 4 + c] -= f * inv[col * 4 + c];
                }
            }
        }

        return inv;
    }
}
