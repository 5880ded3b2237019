namespace GMac.Dsl.Tests.Support;

/// <summary>Small definitions that tests build on.</summary>
internal static class DslSnippets
{
    public const string E3d = """
        define frame e3d as basis: {e1, e2, e3} Euclidean end frame
        define subspace e3d.vectors as basis {e1, e2, e3} end subspace
        define subspace e3d.scalars as basis {1} end subspace
        define subspace e3d.bivectors as basis {e1^e2, e2^e3, e1^e3} end subspace
        define multivector class e3d.Vector as vectors end multivector class
        define multivector class e3d.Scalar as scalars end multivector class
        define multivector class e3d.Bivector as bivectors end multivector class
        define constant e3d.Ii as multivector { e3^e2^e1 : 1 } end constant
        define frame e2d as basis: {e1, e2} Euclidean end frame
        define subspace e2d.vectors as basis {e1, e2} end subspace
        define multivector class e2d.Vector as vectors end multivector class
        define macro UsesPrelude as
            inputs: { u : e3d.Vector; w : e3d.Bivector; s : e3d.Scalar }
            outputs: { x : e3d.Multivector }
            performs: x = u gp e3d.Ii + w + s;
        end macro
        """;
}
