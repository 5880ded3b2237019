namespace Twister.Tessellation;

/// <summary>A vertex on the boundary of a leaf cell, with its integer grid coordinates.</summary>
internal readonly record struct BoundaryVertex(int Id, long I, long J);
