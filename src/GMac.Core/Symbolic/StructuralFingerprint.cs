using System.Numerics;
using System.Runtime.CompilerServices;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// A 128-bit digest of an expression's canonical structure, equal on every run and machine, so it
/// can key answers kept on disk. Scalars, monomials and atoms are shared immutable nodes, and each
/// remembers its digest, so a digest costs one visit per distinct node: printing the same
/// expression as text costs its tree size, which shared subexpressions make far larger.
/// </summary>
internal static class StructuralFingerprint
{
    private const ulong SeedA = 0x243F6A8885A308D3, SeedB = 0x13198A2E03707344;

    /// <summary>Two independently mixed 64-bit lanes; a collision needs both to collide.</summary>
    internal struct Hasher()
    {
        private ulong _a = SeedA, _b = SeedB;

        public void Add(ulong word)
        {
            _a = Mix(_a ^ word) + 0x9E3779B97F4A7C15;
            _b = Mix(BitOperations.RotateLeft(_b, 23) + word * 0xC2B2AE3D27D4EB4F);
        }

        public void Add(UInt128 digest)
        {
            Add((ulong)digest);
            Add((ulong)(digest >> 64));
        }

        public void Add(string text)
        {
            Add((ulong)text.Length);
            foreach (var c in text) Add((ulong)c);
        }

        public void Add(Rational value)
        {
            Add(value.Numerator);
            Add(value.Denominator);
        }

        private void Add(BigInteger value)
        {
            if (value >= long.MinValue && value <= long.MaxValue)
            {
                Add(1UL);
                Add((ulong)(long)value);
                return;
            }
            var bytes = value.ToByteArray();
            Add(2UL);
            Add((ulong)bytes.Length);
            foreach (var b in bytes) Add((ulong)b);
        }

        public readonly UInt128 Digest => new(Mix(_a ^ _b), Mix(_b + SeedA));

        /// <summary>The SplitMix64 finalizer: every input bit affects every output bit.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static ulong Mix(ulong x)
        {
            x ^= x >> 30;
            x *= 0xBF58476D1CE4E5B9;
            x ^= x >> 27;
            x *= 0x94D049BB133111EB;
            return x ^ (x >> 31);
        }
    }

    public static UInt128 Of(Scalar scalar)
    {
        var hasher = new Hasher();
        var terms = scalar.TermArray;
        hasher.Add(0x5CA1A7UL);
        hasher.Add((ulong)terms.Length);
        foreach (var term in terms)
        {
            hasher.Add(term.Coefficient);
            hasher.Add(term.Monomial.Fingerprint);
        }
        return hasher.Digest;
    }

    public static UInt128 Of(Monomial monomial)
    {
        var hasher = new Hasher();
        var factors = monomial.FactorArray;
        hasher.Add(0x30A01UL);
        hasher.Add((ulong)factors.Length);
        foreach (var factor in factors)
        {
            hasher.Add(factor.Atom.Fingerprint);
            hasher.Add((ulong)(long)factor.Power);
        }
        return hasher.Digest;
    }

    public static UInt128 Of(Atom atom)
    {
        var hasher = new Hasher();
        hasher.Add(0xA70AUL);
        hasher.Add((ulong)atom.Kind);
        hasher.Add(atom.Name);
        var arguments = atom.ArgumentArray;
        hasher.Add((ulong)arguments.Length);
        foreach (var argument in arguments) hasher.Add(argument.Fingerprint);
        return hasher.Digest;
    }
}
