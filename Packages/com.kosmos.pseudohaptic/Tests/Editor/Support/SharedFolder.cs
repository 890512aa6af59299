using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// What a test does when the project's shared folder (../shared beside the repository) lacks what it needs: in a
    /// user's clone or Unity project the folder is absent and the test is ignored, with the reason; in the project's
    /// CI (environment variable CI=true, which <c>.ci/run</c> sets), where the folder must be present, the test fails,
    /// so a missing or moved file is never silently skipped.
    /// </summary>
    internal static class SharedFolder
    {
        public static bool IsCi => string.Equals(Environment.GetEnvironmentVariable("CI"), "true", StringComparison.OrdinalIgnoreCase);

        public static void Missing(string reason)
        {
            if (IsCi) Assert.Fail(reason + "; CI=true, where ../shared must be present");
            Assert.Ignore(reason);
        }
    }
}
