using System.Linq;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// How the strace tests read strace's output (<see cref="SelfTrace.Parse"/>): a call another thread interrupted comes in
    /// two lines, which must make one call, or a busy machine makes a syscall test fail (it did once, under mutation testing).
    /// </summary>
    public class SelfTraceParseTests
    {
        [Test]
        public void ACallInterruptedByAnotherThreadIsJoinedFromItsTwoLines()
        {
            var calls = SelfTrace.Parse(new[]
            {
                "100 openat(AT_FDCWD, \"/tmp/x/.ph0a1b2c3d.tmp\", O_WRONLY|O_CREAT|O_EXCL|O_CLOEXEC, 0666 <unfinished ...>",
                "101 write(2</dev/pts/0>, \"x\", 1) = 1",
                "100 <... openat resumed>) = 5</tmp/x/.ph0a1b2c3d.tmp>",
                "100 fsync(5</tmp/x/.ph0a1b2c3d.tmp> <unfinished ...>",
                "101 fsync(7</tmp/y>) = -1 EIO (Input/output error) (INJECTED)",
                "100 <... fsync resumed>) = 0",
                "100 rename(\"/tmp/x/.ph0a1b2c3d.tmp\", \"/tmp/x/r.csv\") = 0",
                "102 <... fsync resumed>) = 0", // its first line was before the trace began: no call
            });
            Assert.That(calls.Select(c => c.ToString()), Is.EqualTo(new[]
            {
                "write(2</dev/pts/0>, \"x\", 1) = 1",
                "openat(AT_FDCWD, \"/tmp/x/.ph0a1b2c3d.tmp\", O_WRONLY|O_CREAT|O_EXCL|O_CLOEXEC, 0666) = 5",
                "fsync(7</tmp/y>) = -1",
                "fsync(5</tmp/x/.ph0a1b2c3d.tmp>) = 0",
                "rename(\"/tmp/x/.ph0a1b2c3d.tmp\", \"/tmp/x/r.csv\") = 0",
            }));
            Assert.That(calls[1].Paths, Is.EqualTo(new[] { "/tmp/x/.ph0a1b2c3d.tmp" }));
            Assert.That(calls[3].DescriptorPath, Is.EqualTo("/tmp/x/.ph0a1b2c3d.tmp"));
        }
    }
}
