namespace RayTracer.Scenes.Instancing;

/// <summary>The five ways of placing a cylinder that thesis §7.2.1 (Table 7-2) compares.</summary>
public enum CylinderMethod
{
    /// <summary>The hand-derived universal cylinder (<see cref="Geometry.Universal.Cylinder"/>).</summary>
    UCyl,

    /// <summary>The universal cylinder with RSTR folded into its generated intersection.</summary>
    GauCyl,

    /// <summary>A matrix <see cref="Geometry.Instance"/> of the generic tube.</summary>
    ICyl,

    /// <summary>A <see cref="Geometry.Instancing.TsrInstance"/> of the generic tube.</summary>
    TsrCyl,

    /// <summary>An <see cref="Geometry.Instancing.RstrInstance"/> of the generic tube.</summary>
    RstrCyl,
}
