using System.Numerics;

namespace RayTracer.Maths;

/// <summary>
/// The design shared by the renderer's three-component values (<see cref="Point3D"/>, <see cref="Vector3D"/>,
/// <see cref="Normal3D"/> and <see cref="Colors.RGBColor"/>): three public doubles, exact component-wise
/// equality and scaling by a number. Each type adds only the operations its algebra allows: a point minus a
/// point is a vector, a point plus a vector is a point, normals are carried by the inverse transpose, and
/// colours multiply channel by channel. The member bodies common to all of them live in <see cref="Tuple3"/>.
/// </summary>
public interface ITuple3<TSelf> : IEquatable<TSelf>, IEqualityOperators<TSelf, TSelf, bool>, IMultiplyOperators<TSelf, double, TSelf>
    where TSelf : struct, ITuple3<TSelf>
{
    /// <summary>The value with these three components.</summary>
    static abstract TSelf Create(double first, double second, double third);

    /// <summary>The components in order (x, y, z or r, g, b).</summary>
    (double First, double Second, double Third) Components { get; }
}
