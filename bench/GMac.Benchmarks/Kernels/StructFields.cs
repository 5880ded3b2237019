using System.Reflection;

namespace GMac.Benchmarks.Kernels;

/// <summary>The doubles of a struct of doubles and nested such structs, in declaration order: the columns of its items.</summary>
public static class StructFields
{
    public static double[] Doubles(object value)
    {
        var doubles = new List<double>();
        Add(value, doubles);
        return doubles.ToArray();
    }

    private static void Add(object value, List<double> doubles)
    {
        if (value is double d)
        {
            doubles.Add(d);
            return;
        }
        foreach (var field in value.GetType().GetFields(BindingFlags.Public | BindingFlags.Instance).OrderBy(f => f.MetadataToken))
            Add(field.GetValue(value)!, doubles);
    }
}
