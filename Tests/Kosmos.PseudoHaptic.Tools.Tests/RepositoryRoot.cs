using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>Finds the repository (and the shared folder beside it, where one exists) from the test's directory.</summary>
public static class RepositoryRoot
{
    public static string Path { get; } = Find();

    static string Find()
    {
        for (var dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); dir != null; dir = dir.Parent)
            if (File.Exists(System.IO.Path.Combine(dir.FullName, "Packages", "com.kosmos.pseudohaptic", "package.json")))
                return dir.FullName;
        throw new InvalidOperationException("the repository root (with Packages/com.kosmos.pseudohaptic) is not above " + TestContext.CurrentContext.TestDirectory);
    }

    /// <summary>../shared beside the clone: present here and in CI, absent beside a user's clone.</summary>
    public static string? Shared
    {
        get
        {
            string p = System.IO.Path.GetFullPath(System.IO.Path.Combine(Path, "..", "shared"));
            if (Directory.Exists(p)) return p;
            // In the project's CI (CI=true, set by .ci/run) ../shared must be there: a test that needs it fails
            // instead of being ignored. In a user's clone it is absent and such tests are ignored.
            if (string.Equals(Environment.GetEnvironmentVariable("CI"), "true", StringComparison.OrdinalIgnoreCase))
                Assert.Fail("../shared is absent beside " + Path + "; CI=true, where it must be present");
            return null;
        }
    }
}
