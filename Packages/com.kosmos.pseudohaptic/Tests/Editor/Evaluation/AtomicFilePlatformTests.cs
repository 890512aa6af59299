using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// <see cref="AtomicFile"/>'s branches for Windows and macOS, run here on Linux by choosing the platform
    /// (<c>AtomicFile.PlatformForTests</c>) and watched with strace (<see cref="SelfTrace"/>): the file synced once by .NET's own
    /// <c>Flush(true)</c>, not by the libc call that checks its result; on Windows no folder synced; on macOS the folder
    /// opened without O_CLOEXEC and its ENOTSUP taken as a refusal. The kernel answering is Linux's, so what is checked is
    /// which calls each branch makes, not the other platform's file system (Linux with strace; ignored elsewhere).
    /// </summary>
    public class AtomicFilePlatformTests : AtomicFileTracing
    {
        [Test]
        public void TheTestsRunOnLinux()
        {
            // Without a platform chosen, the running one: what every other test of AtomicFile expects.
            if (!System.Runtime.InteropServices.RuntimeInformation.IsOSPlatform(System.Runtime.InteropServices.OSPlatform.Linux)) Assert.Ignore("Linux only");
            Assert.That(AtomicFile.Platform, Is.EqualTo(AtomicFile.SyncPlatform.Linux));
        }

        [Test]
        public void OnWindowsTheFileIsSyncedOnceBeforeItsRenameAndNoFolderIsSynced()
        {
            AtomicFile.PlatformForTests = AtomicFile.SyncPlatform.Windows;
            string target = Path.Combine(_dir, "trials.csv"), nested = Path.Combine(_dir, "a", "b");
            var calls = Traced(() =>
            {
                AtomicFile.WriteAllText(target, "x");
                AtomicFile.CreateDirectory(nested);
            }, _dir);
            string temp = TemporaryOf(calls);
            Assert.That(calls, Is.EqualTo(new[] { "fsync " + temp, "rename " + temp + " -> " + target, "mkdir " + Path.Combine(_dir, "a"), "mkdir " + nested }));
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Unsupported));
            Assert.That(File.ReadAllText(target), Is.EqualTo("x"));
        }

        [Test]
        public void OnMacOSTheFileIsSyncedOnceByDotNetAndTheFolderThroughLibcWithoutCloseOnExec()
        {
            AtomicFile.PlatformForTests = AtomicFile.SyncPlatform.MacOS;
            string target = Path.Combine(_dir, "trials.csv");
            List<SelfTrace.Call> calls;
            using (var trace = SelfTrace.Start(_dir, "openat,fsync,rename,renameat,renameat2"))
            {
                try { AtomicFile.WriteAllText(target, "x"); }
                finally { calls = trace.Stop(); }
            }
            var fsyncs = calls.Where(c => c.Name == "fsync" && (c.DescriptorPath ?? "").StartsWith(_dir, StringComparison.Ordinal)).ToList();
            Assert.That(fsyncs.Select(c => c.DescriptorPath == _dir ? "folder" : "file"), Is.EqualTo(new[] { "file", "folder" }), string.Join("\n", calls));
            var folderOpen = calls.Last(c => c.Name == "openat" && c.Paths.Length > 0 && c.Paths[0] == _dir);
            StringAssert.Contains("O_RDONLY", folderOpen.Args);
            StringAssert.DoesNotContain("O_CLOEXEC", folderOpen.Args, "macOS's O_CLOEXEC has another value: left out");
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Synced));
        }

        [TestCase("Windows")]
        [TestCase("MacOS")]
        public void OnWindowsAndMacOSTheFileSyncIsDotNetsOwnWhichDoesNotCheckIt(string platform)
        {
            // The sign that the file's sync is .NET's Flush(true) and not this class's libc call: a failure injected into it
            // passes here (.NET on Linux does not report it), where the libc call reports it (AtomicFileSyscallTests.
            // AFileSyncThatFailsIsAnErrorNamingTheFileAndNothingIsLeft). On Windows and macOS .NET reports its own failures.
            AtomicFile.PlatformForTests = (AtomicFile.SyncPlatform)Enum.Parse(typeof(AtomicFile.SyncPlatform), platform);
            string target = Path.Combine(_dir, "trials.csv");
            var calls = Traced(() => AtomicFile.WriteAllText(target, "x"), _dir, "fsync:error=EIO:when=1");
            Assert.That(calls[0], Does.EndWith(" = -1"), string.Join("\n", calls));
            Assert.That(calls.Count(c => c.StartsWith("fsync " + TemporaryOf(calls), StringComparison.Ordinal)), Is.EqualTo(1), "synced once, not again by libc");
            Assert.That(File.ReadAllText(target), Is.EqualTo("x"));
        }

        [Test]
        public void OnMacOSAFolderSyncRefusedWithEnotsupIsNoErrorAndAnEioIs()
        {
            // errno 45 is ENOTSUP on macOS (a file system that cannot sync a folder); on Linux it is an error
            // (AtomicFileSyscallTests.AFolderSyncThatFailsIsAnErrorNamingTheFolder). The folder's fsync is the second.
            AtomicFile.PlatformForTests = AtomicFile.SyncPlatform.MacOS;
            string target = Path.Combine(_dir, "trials.csv");
            Traced(() => AtomicFile.WriteAllText(target, "x"), _dir, "fsync:error=45:when=2");
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Refused));
            IOException error = null;
            Traced(() => error = Assert.Throws<IOException>(() => AtomicFile.WriteAllText(target, "y")), _dir, "fsync:error=EIO:when=2");
            Assert.That(error.Message, Is.EqualTo(_dir + ": the folder could not be synced to the device (errno 5)"));
        }
    }
}
