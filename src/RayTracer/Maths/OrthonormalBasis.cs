namespace RayTracer.Maths;

/// <summary>Right-handed orthonormal frame (u, v, w) built around a given w.</summary>
public readonly struct OrthonormalBasis
{
    public readonly Vector3D U;
    public readonly Vector3D V;
    public readonly Vector3D W;

    public OrthonormalBasis(Vector3D u, Vector3D v, Vector3D w)
    {
        U = u;
        V = v;
        W = w;
    }

    /// <summary>Frame whose w is the normalized <paramref name="direction"/>; u and v are arbitrary but continuous (Duff et al. 2017).</summary>
    public static OrthonormalBasis FromW(Vector3D direction)
    {
        var w = direction.Normalized();
        double sign = Math.CopySign(1.0, w.z);
        double a = -1.0 / (sign + w.z);
        double b = w.x * w.y * a;
        var u = new Vector3D(1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x);
        var v = new Vector3D(b, sign + w.y * w.y * a, -w.y);
        return new OrthonormalBasis(u, v, w);
    }

    public Vector3D ToWorld(double a, double b, double c) => a * U + b * V + c * W;
}
