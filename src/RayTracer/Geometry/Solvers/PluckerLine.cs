namespace RayTracer.Geometry.Solvers;

/// <summary>
/// A line as the projective bivector (a + eo) ∧ (b + eo): the moment a × b in the e1∧e2, e2∧e3, e1∧e3
/// coefficients and the direction a − b in the e_i∧eo coefficients (binding PluckerLine in dsl/).
/// </summary>
public struct PluckerLine
{
    public double xy;
    public double yz;
    public double xz;
    public double xo;
    public double yo;
    public double zo;
}
