using System.Globalization;
using QuickStart;

// Each line prints a result of GMac-generated code next to the same quantity computed by hand.
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;

var u = new Vec3(1, 2, 3);
var v = new Vec3(-2, 0.5, 4);
Console.WriteLine("Normal to two vectors (u ^ v) . I^-1");
Console.WriteLine($"  u = {u}, v = {v}");
Console.WriteLine($"  GMac:     {GeometryKernels.NormalToVectors(u, v)}");
Console.WriteLine($"  expected: {Expectations.Normal(u, v)}");

Vec3 a = new(3, 1, 2), b = new(-1, 1, 2), c = new(1, 3, 2), d = new(1, 1, 4);
var (centre, radius) = GeometryKernels.SphereThroughPoints(a, b, c, d);
var (expectedCentre, expectedRadius) = Expectations.Sphere(a, b, c, d);
Console.WriteLine("Sphere through four points (cga5d: p1 ^ p2 ^ p3 ^ p4, dualized)");
Console.WriteLine($"  points {a} {b} {c} {d}");
Console.WriteLine($"  GMac:     centre {centre}, radius {radius:0.000000}");
Console.WriteLine($"  expected: centre {expectedCentre}, radius {expectedRadius:0.000000}");

var point = new Vec3(2, 0, 1);
var through = new Vec3(1, 1, 0);
var axis = new Vec3(0, 0, 2);
var angle = Math.PI / 3;
Console.WriteLine("Rotation of a point about the axis through a point (general rotation versor)");
Console.WriteLine($"  point {point}, axis {axis} through {through}, angle pi/3");
Console.WriteLine($"  GMac:     {GeometryKernels.RotateAboutLine(point, through, axis, angle)}");
Console.WriteLine($"  expected: {Expectations.Rotate(point, through, axis, angle)}");
