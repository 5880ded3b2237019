using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Rewrites;

/// <summary>
/// √P where P + u² reduces to a constant c under the side relations, and the block also reads u
/// whole, as the argument of |u| or of atan2: u is named once and the root reads √(c − u²). For a
/// unit rotor Q = R₂R̃₁ this is ‖⟨Q⟩₂‖ = √(1 − ⟨Q⟩₀²), which the canonical form otherwise writes as
/// the expanded sum of squares of the bivector part reduced by the unit constraints, a polynomial
/// of dozens of terms.
/// </summary>
internal static class NormComplement
{
    private const int MaxPairs = 16;

    public static void Apply(List<SymbolicInliner.Assignment> assignments, Func<Scalar, Scalar> simplify)
    {
        var reads = new Dictionary<Scalar, List<Atom>>(); // each u with the atoms reading it whole
        var roots = new List<Atom>();
        foreach (var a in assignments) Collect(a.Value, reads, roots, new HashSet<Atom>());
        if (reads.Count == 0 || roots.Count == 0 || reads.Count * roots.Count > MaxPairs) return;

        var replacements = new Dictionary<Atom, Scalar>();
        var named = new List<(string Name, Scalar Value)>();
        var renamedReads = new List<(Atom Reader, Scalar U, Scalar T)>();
        foreach (var (u, readers) in reads)
        {
            string? name = null;
            foreach (var root in roots)
            {
                var p = root.ArgumentArray[0];
                if (replacements.ContainsKey(root) || !u.Variables.IsSubsetOf(p.Variables)) continue;
                if (!simplify(p + u * u).TryGetConstant(out var c) || c.Sign <= 0) continue;
                var t = Scalar.Variable(name ?? $"{TemporaryRecorder.Prefix}n{named.Count}");
                var complement = Scalar.Constant(c) - t * t;
                if (Cost(complement) + Cost(u) >= Cost(p)) continue;
                if (name is null)
                {
                    name = t.Variables.First();
                    named.Add((name, u));
                    foreach (var reader in readers) renamedReads.Add((reader, u, t));
                }
                replacements[root] = Scalar.Sqrt(complement);
            }
        }
        if (named.Count == 0) return;
        // readers last: their other arguments may hold a replaced root (atan2(√P, u))
        var rootMemo = new Dictionary<Atom, Scalar>();
        foreach (var (reader, u, t) in renamedReads) replacements[reader] = Reading(reader, u, t, replacements, rootMemo);

        var memo = new Dictionary<Atom, Scalar>();
        foreach (var a in assignments)
            a.Value = Scalar.MapAtoms(a.Value, atom => replacements.GetValueOrDefault(atom), memo);
        // Each name goes right before the first value that reads it, where all that u reads is known.
        foreach (var (name, value) in named)
        {
            foreach (var a in assignments) a.Value = Reuse(a.Value, value, Scalar.Variable(name), simplify);
            var first = assignments.FindIndex(a => a.Value.Variables.Contains(name));
            assignments.Insert(first < 0 ? 0 : first, new SymbolicInliner.Assignment(name, value, false));
        }
    }

    /// <summary>The reading atom with its argument u replaced by the name t, and the roots in its other arguments replaced.</summary>
    private static Scalar Reading(Atom reader, Scalar u, Scalar t, Dictionary<Atom, Scalar> roots, Dictionary<Atom, Scalar> memo)
    {
        var a = reader.ArgumentArray;
        Scalar Swap(Scalar x) => ReferenceEquals(x, u) ? t : Scalar.MapAtoms(x, atom => atom.Kind == AtomKind.Sqrt ? roots.GetValueOrDefault(atom) : null, memo);
        return reader.Kind == AtomKind.Abs ? Scalar.Abs(t) : Scalar.Atan2(Swap(a[0]), Swap(a[1]));
    }

    /// <summary>
    /// v written as q·t + r for the named t = u, when cheaper: q and r from dividing v by u, r then
    /// reduced by the side relations (the unit constraint w² + x² + … = 1 folds what the division
    /// leaves, as in the scalar part of (Q − s)R₁ = R₂ − s R₁). Every atom of u is tried as the lead.
    /// </summary>
    private static Scalar Reuse(Scalar v, Scalar u, Scalar t, Func<Scalar, Scalar> simplify)
    {
        if (!u.Variables.Overlaps(v.Variables)) return v;
        var best = v;
        var bestCost = Cost(v);
        foreach (var first in PolynomialRemainder.Candidates(u))
        {
            if (!PolynomialRemainder.TryDivide(v, u, first, out var q, out var r) || Scalar.IsZero(q)) continue;
            var candidate = q * t + simplify(r);
            var cost = Cost(candidate);
            if (cost < bestCost) (best, bestCost) = (candidate, cost);
        }
        return best;
    }

    /// <summary>Sums read whole by |u| or atan2, and roots √P of sums, at any depth.</summary>
    private static void Collect(Scalar s, Dictionary<Scalar, List<Atom>> reads, List<Atom> roots, HashSet<Atom> seen)
    {
        foreach (var term in s.TermArray)
        foreach (var factor in term.Monomial.FactorArray)
        {
            var atom = factor.Atom;
            if (!seen.Add(atom)) continue;
            foreach (var argument in atom.ArgumentArray) Collect(argument, reads, roots, seen);
            if (atom.Kind == AtomKind.Sqrt && atom.Arguments[0].Terms.Count >= 2) roots.Add(atom);
            if (atom.Kind is not (AtomKind.Abs or AtomKind.Atan2)) continue;
            foreach (var argument in atom.ArgumentArray)
            {
                if (argument.Terms.Count < 2) continue;
                if (!reads.TryGetValue(argument, out var readers)) reads[argument] = readers = [];
                if (!readers.Contains(atom)) readers.Add(atom);
            }
        }
    }

    private static int Cost(Scalar s) => CodeStatistics.CostOf(ScalarLowering.Lower(s));
}
