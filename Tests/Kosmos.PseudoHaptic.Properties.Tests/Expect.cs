namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>
/// Assertions for a property's body. Not NUnit's: a failed <c>Assert</c> is recorded in the running test's result even
/// when FsCheck catches it, so every case FsCheck tries while it shrinks would be reported; these only throw, and
/// <see cref="Checks"/> reports the shrunk case once.
/// </summary>
static class Expect
{
    public static void AtMost(double actual, double bound, string what)
    {
        if (!(actual <= bound)) throw new PropertyFailed($"{what}: {actual:R}, more than {bound:R}");
    }

    public static void That(bool condition, string what)
    {
        if (!condition) throw new PropertyFailed(what);
    }
}

sealed class PropertyFailed : Exception
{
    public PropertyFailed(string message) : base(message) { }
}
