namespace RayTracer.Acceleration;

/// <summary>
/// A leaf of the wide BVH: primitives [First, First + Count) of the table, and, when all of them are
/// Möller–Trumbore triangles, the run of four- or eight-lane groups [Group, Group + GroupCount) that holds them
/// (Group is −1 otherwise). <see cref="GroupsCastShadows"/> says whether every one of them casts
/// shadows, so the any-hit query may test the groups instead of the primitives one by one.
/// </summary>
internal struct BvhLeaf
{
    public int First;
    public int Count;
    public int Group;
    public int GroupCount;
    public bool GroupsCastShadows;
}
