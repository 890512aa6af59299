using System.Runtime.CompilerServices;

// The edit-mode tests choose the platform whose file syncs AtomicFile makes (AtomicFile.PlatformForTests), so that each
// platform's branch runs on the Linux machines that test the package.
[assembly: InternalsVisibleTo("Kosmos.PseudoHaptic.Tests.Editor")]
