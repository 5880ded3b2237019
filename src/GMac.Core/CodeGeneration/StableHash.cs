namespace GMac.Core.CodeGeneration;

/// <summary>
/// Deterministic hashing for expression nodes. System.HashCode is seeded per process, and any
/// choice that depends on it would make generated code differ from run to run.
/// </summary>
internal static class StableHash
{
    public static int Of(string s)
    {
        unchecked
        {
            var h = (int)2166136261;
            foreach (var c in s) h = (h ^ c) * 16777619;
            return h;
        }
    }

    public static int Of(double d)
    {
        var bits = BitConverter.DoubleToInt64Bits(d == 0 ? 0.0 : d); // +0 and −0 hash alike, as they compare equal
        return unchecked((int)bits ^ (int)(bits >> 32));
    }

    public static int Combine(int a, int b) => unchecked((a * 1_000_003) ^ b ^ (b >> 15) + (a << 7));
}
