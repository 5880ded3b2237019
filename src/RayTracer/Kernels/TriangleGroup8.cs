namespace RayTracer.Kernels;

/// <summary>
/// Eight triangles as the Möller–Trumbore test wants them (v0 and the edges e1 = v1 − v0, e2 = v2 − v0),
/// one per lane. An unused lane holds zero edges, whose determinant is zero, so it never hits.
/// </summary>
internal struct TriangleGroup8
{
    public Vector3x8 V0;
    public Vector3x8 E1;
    public Vector3x8 E2;
}
