using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>A test that needs ../shared is ignored in a user's clone but fails in the project's CI (CI=true).</summary>
    public class SharedDataTests
    {
        [Test]
        public void MissingSharedDataFailsUnderCiAndIsIgnoredElsewhere()
        {
            string before = Environment.GetEnvironmentVariable("CI");
            try
            {
                Environment.SetEnvironmentVariable("CI", "true");
                Assert.Throws<AssertionException>(() => SharedFolder.Missing("absent"), "CI=true: fail");
                Environment.SetEnvironmentVariable("CI", null);
                Assert.Throws<IgnoreException>(() => SharedFolder.Missing("absent"), "a user's clone: ignore");
            }
            finally
            {
                Environment.SetEnvironmentVariable("CI", before);
            }
        }
    }
}
