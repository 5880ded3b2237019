namespace GMac.Core.CodeGeneration;

/// <summary>
/// The input variables that are the coordinates of one point or vector of the macro, in the order
/// of its basis blades. Points with the same <see cref="Layout"/> (frame and blades) can be
/// subtracted coordinate by coordinate: a value that moves with them may be written over their
/// differences from one of them (see <see cref="Passes.TranslationInvariancePass"/>).
/// <see cref="IsPosition"/>: the input is a position, a point with a constant weight (the no = 1
/// of a normalized conformal point), not a direction: its absolute coordinates mean nothing on
/// their own, and values of positions are written relative to one of them where that keeps digits.
/// </summary>
public sealed record InputPoint(string Layout, IReadOnlyList<string> Coordinates, bool IsPosition = false);
