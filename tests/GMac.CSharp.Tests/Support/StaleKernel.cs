namespace GMac.CSharp.Tests.Support;

/// <summary>A C# file with one binding point whose body is stale, for tests of how files are written.</summary>
internal static class StaleKernel
{
    public const string StaleLine = "        stale text that the generator replaces";

    public const string Text = """
        namespace Sample;

        public static class Normals
        {
            public static (double, double, double) Get(double ux, double uy, double uz, double vx, double vy, double vz)
            {
                double wx, wy, wz;
                #region GMac : GetNormalToVectors
                //GMac.Bind("u.e1", ux);
                //GMac.Bind("u.e2", uy);
                //GMac.Bind("u.e3", uz);
                //GMac.Bind("v.e1", vx);
                //GMac.Bind("v.e2", vy);
                //GMac.Bind("v.e3", vz);
                //GMac.Bind("w.e1", wx);
                //GMac.Bind("w.e2", wy);
                //GMac.Bind("w.e3", wz);
                stale text that the generator replaces
                #endregion
                return (wx, wy, wz);
            }
        }

        """;

    /// <summary>An assignment the generated body has (the cross product's first coefficient).</summary>
    public const string GeneratedMarker = "wx = ";
}
