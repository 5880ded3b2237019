namespace GMac.Benchmarks.Kernels.Values;

/// <summary>The five joint angles (radians) of the inverse-kinematics arm.</summary>
public struct JointAngles
{
    public double A1;
    public double A2;
    public double A3;
    public double A4;
    public double A5;
}
