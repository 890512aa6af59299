using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// What <see cref="AtomicFile"/> asks of the kernel, seen by strace attached to this test process (<see cref="SelfTrace"/>):
    /// the file's data synced before its rename, the folder synced after it, nothing synced twice or not at all, and a
    /// failing or refused sync (strace's fault injection makes the next <c>fsync</c> fail with a chosen errno) reported as
    /// its documented contract says. The command-line tool's DurabilityTests check the same order for a whole study session
    /// in a child process; these check the writer itself, in the process that runs it (Linux with strace; ignored elsewhere).
    /// </summary>
    public class AtomicFileSyscallTests : AtomicFileTracing
    {
        [Test]
        public void AWriteSyncsTheFileThenRenamesItThenSyncsTheFolder([Values(false, true)] bool replacing)
        {
            string target = Path.Combine(_dir, "responses.csv");
            if (replacing) File.WriteAllText(target, "old");
            var calls = Traced(() => AtomicFile.WriteAllText(target, "a,b\n"), _dir);
            string temp = TemporaryOf(calls);
            Assert.That(calls, Is.EqualTo(new[] { "fsync " + temp, "rename " + temp + " -> " + target, "fsync " + _dir }));
            Assert.That(File.ReadAllText(target), Is.EqualTo("a,b\n"));
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Synced));
        }

        [Test]
        public void AWriterThatDoesNotSyncIsSyncedForItAndOneThatSaysItDidIsNotSyncedAgain()
        {
            string target = Path.Combine(_dir, "trials.csv");
            var unsynced = Traced(() => AtomicFile.WriteWith(target, temp => File.WriteAllText(temp, "x")), _dir);
            string temp1 = TemporaryOf(unsynced);
            Assert.That(unsynced, Is.EqualTo(new[] { "fsync " + temp1, "rename " + temp1 + " -> " + target, "fsync " + _dir }));

            var selfSynced = Traced(() => AtomicFile.Write(target, synced: true, write: temp =>
            {
                using (var s = new FileStream(temp, FileMode.CreateNew, FileAccess.Write))
                {
                    s.WriteByte(42);
                    AtomicFile.SyncStream(s);
                }
            }), _dir);
            string temp2 = TemporaryOf(selfSynced);
            Assert.That(selfSynced, Is.EqualTo(new[] { "fsync " + temp2, "rename " + temp2 + " -> " + target, "fsync " + _dir }), "synced once, by the writer");

            // A writer that says it synced is believed: only the rename and the folder.
            var believed = Traced(() => AtomicFile.Write(target, synced: true, write: temp => File.WriteAllText(temp, "y")), _dir);
            string temp3 = TemporaryOf(believed);
            Assert.That(believed, Is.EqualTo(new[] { "rename " + temp3 + " -> " + target, "fsync " + _dir }));
        }

        [Test]
        public void TheDataIsWrittenBeforeItIsSyncedAndTheFolderIsOpenedCloseOnExec()
        {
            // The text goes from the stream's buffer to the file (write) before the fsync, not when the stream is closed after
            // it; the folder is opened read-only with O_CLOEXEC, so a child process started meanwhile does not inherit it.
            string target = Path.Combine(_dir, "responses.csv");
            List<SelfTrace.Call> calls;
            using (var trace = SelfTrace.Start(_dir, "write,pwrite64,pwritev,pwritev2,openat,fsync,rename,renameat,renameat2"))
            {
                try { AtomicFile.WriteAllText(target, "a,b\n"); }
                finally { calls = trace.Stop(); }
            }
            var mine = calls.Where(c => (c.DescriptorPath ?? "").StartsWith(_dir, StringComparison.Ordinal) && c.Name != "openat"
                || c.Name == "openat" && c.Paths.Length > 0 && c.Paths[0].StartsWith(_dir, StringComparison.Ordinal)).ToList();
            string Shown(SelfTrace.Call c) => (c.Name.StartsWith("pwrite", StringComparison.Ordinal) ? "write" : c.Name) + " " + (c.Name == "openat" ? c.Paths[0] : c.DescriptorPath);
            string temp = mine.First(c => c.Name == "openat").Paths[0];
            Assert.That(AtomicFile.IsTemporaryName(Path.GetFileName(temp)), Is.True, temp);
            var order = mine.Where(c => !c.Name.StartsWith("rename", StringComparison.Ordinal)).Select(Shown).ToList();
            Assert.That(order, Is.EqualTo(new[] { "openat " + temp, "write " + temp, "fsync " + temp, "openat " + _dir, "fsync " + _dir }),
                string.Join("\n", mine));
            var folderOpen = mine.Last(c => c.Name == "openat");
            StringAssert.Contains("O_RDONLY|O_CLOEXEC", folderOpen.Args);
            StringAssert.DoesNotContain("O_WRONLY", folderOpen.Args);
        }

        [Test]
        public void AFolderThatCannotBeOpenedToSyncItIsAnErrorNamingIt()
        {
            // Only the calls on the folder itself are traced (-P), so its open is the first openat: EACCES.
            string target = Path.Combine(_dir, "responses.csv");
            IOException error = null;
            List<SelfTrace.Call> calls;
            using (var trace = SelfTrace.Start(_dir, "openat", "openat:error=EACCES:when=1", path: _dir))
            {
                try { error = Assert.Throws<IOException>(() => AtomicFile.WriteAllText(target, "a")); }
                finally { calls = trace.Stop(); }
            }
            Assert.That(calls.Count(c => c.Result < 0), Is.EqualTo(1), string.Join("\n", calls));
            Assert.That(error.Message, Is.EqualTo(_dir + ": the folder could not be opened to sync it (errno 13)"));
            Assert.That(File.ReadAllText(target), Is.EqualTo("a"), "renamed before the folder's sync");
            Assert.That(Directory.GetFiles(_dir).Count(f => AtomicFile.IsTemporaryName(Path.GetFileName(f))), Is.Zero);
        }

        [Test]
        public void NotDurableNothingIsSynced()
        {
            AtomicFile.Durable = false;
            string target = Path.Combine(_dir, "bench.csv");
            var calls = Traced(() =>
            {
                AtomicFile.WriteAllText(target, "1");
                AtomicFile.WriteWith(target, temp => File.WriteAllText(temp, "2"));
                AtomicFile.CreateDirectory(Path.Combine(_dir, "new"));
            }, _dir);
            Assert.That(calls.Where(c => c.StartsWith("fsync", StringComparison.Ordinal)), Is.Empty);
            Assert.That(calls.Count(c => c.StartsWith("rename ", StringComparison.Ordinal)), Is.EqualTo(2));
            Assert.That(calls.Last(), Is.EqualTo("mkdir " + Path.Combine(_dir, "new")));
            Assert.That(File.ReadAllText(target), Is.EqualTo("2"));
        }

        [Test]
        public void EachFolderCreatedIsFollowedByASyncOfTheFolderAboveIt()
        {
            string a = Path.Combine(_dir, "a"), b = Path.Combine(a, "b"), c = Path.Combine(b, "c");
            var calls = Traced(() => AtomicFile.CreateDirectory(c), _dir);
            Assert.That(calls, Is.EqualTo(new[] { "mkdir " + a, "fsync " + _dir, "mkdir " + b, "fsync " + a, "mkdir " + c, "fsync " + b }));
            Assert.That(Traced(() => AtomicFile.CreateDirectory(c), _dir), Is.Empty, "a folder that exists: nothing");
            Assert.That(Traced(() => AtomicFile.CreateDirectory(""), _dir), Is.Empty);
        }

        [Test]
        public void WithoutFileReplaceTheOldFileIsReplacedByOneRenameNeverRemovedFirst([Values(false, true)] bool synced)
        {
            // A runtime whose File.Replace is not supported: the answers file must never be absent, so no unlink of it
            // before the rename (a kill or power cut between the two would leave only a temporary file, which the
            // session's next start removes).
            AtomicFile.ReplaceUnsupportedForTests = true;
            string target = Path.Combine(_dir, "responses.csv");
            File.WriteAllText(target, "old");
            var calls = SelfTrace.CallsUnder(() =>
            {
                if (synced) AtomicFile.WriteAllText(target, "a,b\n");
                else AtomicFile.WriteWith(target, temp => File.WriteAllText(temp, "a,b\n"));
            }, _dir, Syscalls + ",unlink,unlinkat", _dir);
            string temp = TemporaryOf(calls);
            Assert.That(calls, Is.EqualTo(new[] { "fsync " + temp, "rename " + temp + " -> " + target, "fsync " + _dir }));
            Assert.That(File.ReadAllText(target), Is.EqualTo("a,b\n"));
            Assert.That(Directory.GetFiles(_dir).Count(f => AtomicFile.IsTemporaryName(Path.GetFileName(f))), Is.Zero);
        }

        [Test]
        public void WithoutFileReplaceARenameTheKernelRefusesIsAnErrorNamingTheFileAndTheOldOneStays()
        {
            AtomicFile.ReplaceUnsupportedForTests = true;
            string target = Path.Combine(_dir, "responses.csv");
            File.WriteAllText(target, "old");
            IOException error = null;
            var calls = Traced(() => error = Assert.Throws<IOException>(() => AtomicFile.WriteAllText(target, "new")), _dir, "rename:error=EACCES:when=1+");
            Assert.That(calls.Count(c => c.StartsWith("rename ", StringComparison.Ordinal) && c.EndsWith(" = -1", StringComparison.Ordinal)), Is.EqualTo(9),
                "tried again eight times: " + string.Join("\n", calls));
            Assert.That(error.Message, Is.EqualTo(target + ": could not be replaced (errno 13)"));
            Assert.That(File.ReadAllText(target), Is.EqualTo("old"));
            Assert.That(Directory.GetFiles(_dir).Count(f => AtomicFile.IsTemporaryName(Path.GetFileName(f))), Is.Zero, "the temporary file removed");
        }

        // ---- the kernel says no: strace makes this thread's first (or second) fsync after attaching fail ----------------

        [Test]
        public void AFileSyncThatFailsIsAnErrorNamingTheFileAndNothingIsLeft()
        {
            string target = Path.Combine(_dir, "responses.csv");
            IOException error = null;
            var calls = Traced(() => error = Assert.Throws<IOException>(() => AtomicFile.WriteAllText(target, "a")), _dir, "fsync:error=EIO:when=1");
            Assert.That(calls.Count, Is.EqualTo(1), string.Join("\n", calls));
            string temp = calls[0].Substring(6, calls[0].Length - 6 - 5);
            Assert.That(calls[0], Is.EqualTo("fsync " + temp + " = -1"));
            Assert.That(error.Message, Is.EqualTo(temp + ": the file could not be synced to the device (errno 5)"));
            Assert.That(File.Exists(target), Is.False, "not renamed");
            Assert.That(Directory.GetFiles(_dir).Where(f => !f.EndsWith(".strace", StringComparison.Ordinal)), Is.Empty, "the temporary file removed");
        }

        [Test]
        public void AFolderSyncThatFailsIsAnErrorNamingTheFolder([Values("EIO", "45")] string errno)
        {
            // errno 45 is ENOTSUP on macOS, where the file system's refusal is no error; on Linux it is EL2NSYNC, an error.
            string target = Path.Combine(_dir, "responses.csv");
            IOException error = null;
            var calls = Traced(() => error = Assert.Throws<IOException>(() => AtomicFile.WriteAllText(target, "a")), _dir, "fsync:error=" + errno + ":when=2");
            Assert.That(calls.Last(), Is.EqualTo("fsync " + _dir + " = -1"));
            Assert.That(error.Message, Is.EqualTo(_dir + ": the folder could not be synced to the device (errno " + (errno == "EIO" ? "5" : "45") + ")"));
            Assert.That(File.ReadAllText(target), Is.EqualTo("a"), "renamed before the folder's sync");
        }

        [Test]
        public void ASyncTheFileSystemRefusesIsNoError([Values("EINVAL", "EOPNOTSUPP")] string errno, [Values(1, 2)] int which)
        {
            string target = Path.Combine(_dir, "responses.csv");
            var calls = Traced(() => AtomicFile.WriteAllText(target, "a"), _dir, "fsync:error=" + errno + ":when=" + which);
            Assert.That(calls.Count(c => c.EndsWith(" = -1", StringComparison.Ordinal)), Is.EqualTo(1), string.Join("\n", calls));
            Assert.That(File.ReadAllText(target), Is.EqualTo("a"));
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(which == 2 ? AtomicFile.DirectorySyncKind.Refused : AtomicFile.DirectorySyncKind.Synced));
        }

        [Test]
        public void ASyncASignalInterruptsIsMadeAgain([Values(1, 2)] int which)
        {
            string target = Path.Combine(_dir, "responses.csv");
            var calls = Traced(() => AtomicFile.WriteAllText(target, "a"), _dir, "fsync:error=EINTR:when=" + which);
            string temp = TemporaryOf(calls);
            var expected = new List<string> { "fsync " + temp, "rename " + temp + " -> " + target, "fsync " + _dir };
            int at = which == 1 ? 0 : 2;
            expected.Insert(at, expected[at] + " = -1");
            Assert.That(calls, Is.EqualTo(expected));
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Synced));
        }
    }
}
