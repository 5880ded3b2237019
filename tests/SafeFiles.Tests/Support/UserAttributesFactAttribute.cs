namespace SafeFiles.Tests.Support;

/// <summary>A test of <c>user.*</c> extended attributes: skipped where the temporary folder's file system does not take them.</summary>
internal sealed class UserAttributesFactAttribute : FactAttribute
{
    public UserAttributesFactAttribute()
    {
        var probe = Path.GetTempFileName();
        try
        {
            if (ExtendedAttributes.TrySet(probe, "user.safefiles.probe", [1]) is { } why)
                Skip = $"the file system of {Path.GetTempPath()} does not take user extended attributes: {why}";
        }
        finally
        {
            File.Delete(probe);
        }
    }
}
