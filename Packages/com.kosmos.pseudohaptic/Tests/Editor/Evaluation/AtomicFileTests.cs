using System;
using System.Collections.Generic;
using System.IO;
using System.Runtime.InteropServices;
using System.Threading;
using System.Threading.Tasks;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The durable writer's contract as seen from inside the process: arguments refused naming them, a folder as the
    /// destination refused naming the path, the temporary file next to its destination under the name the cleanup
    /// looks for, the folder sync's outcome (<see cref="AtomicFile.DirectorySync"/>) and errors, no descriptor left
    /// open, and a rename that gives up. (That the data and the folder reach the device in the right order is checked
    /// under strace by the Tools tests' DurabilityTests.)
    /// </summary>
    public class AtomicFileTests
    {
        string dir;

        [SetUp]
        public void SetUp()
        {
            dir = Path.Combine(Path.GetTempPath(), "ph-atomicfile-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
        }

        [TearDown]
        public void TearDown()
        {
            AtomicFile.Durable = true;
            if (Directory.Exists(dir)) Directory.Delete(dir, true);
        }

        static bool IsLinux => RuntimeInformation.IsOSPlatform(OSPlatform.Linux);

        static void RequireLinux(string what)
        {
            if (!IsLinux) Assert.Ignore(what + ": Linux only (libc, /proc)");
        }

        [Test]
        public void NullTextWritesAnEmptyFile()
        {
            string path = Path.Combine(dir, "empty.csv");
            AtomicFile.WriteAllText(path, "old");
            AtomicFile.WriteAllText(path, null);
            Assert.That(File.ReadAllBytes(path), Is.Empty);
        }

        [Test]
        public void TextIsWrittenAsUtf8WithoutAByteOrderMark()
        {
            // A BOM would sit before the header of every CSV the tool and R read ("\uFEFFparticipant" is not "participant").
            string path = Path.Combine(dir, "r.csv");
            AtomicFile.WriteAllText(path, "participant,é\n");
            Assert.That(File.ReadAllBytes(path), Is.EqualTo(new byte[] { (byte)'p', (byte)'a', (byte)'r', (byte)'t', (byte)'i', (byte)'c', (byte)'i',
                (byte)'p', (byte)'a', (byte)'n', (byte)'t', (byte)',', 0xC3, 0xA9, (byte)'\n' }));
        }

        [Test]
        public void SyncingNoStreamIsRefused()
            => Assert.That(Assert.Throws<ArgumentNullException>(() => AtomicFile.SyncStream(null)).ParamName, Is.EqualTo("stream"));

        [Test]
        public void AnEmptyOrNullPathAndANullWriterAreRefusedNamingThem()
        {
            foreach (string bad in new[] { "", null })
            {
                // Exactly ArgumentException (not the ArgumentNullException Path.GetFullPath would throw for null).
                var e = Assert.Throws<ArgumentException>(() => AtomicFile.Write(bad, false, temp => File.WriteAllText(temp, "x")));
                Assert.That(e.ParamName, Is.EqualTo("path"));
                Assert.That(e.Message, Does.StartWith("empty path"), "path " + (bad == null ? "null" : "\"\""));
            }
            var n = Assert.Throws<ArgumentNullException>(() => AtomicFile.WriteWith(Path.Combine(dir, "a.csv"), null));
            Assert.That(n.ParamName, Is.EqualTo("write"));
            Assert.That(Directory.GetFileSystemEntries(dir), Is.Empty, "nothing written");
        }

        [Test]
        public void AFolderAsTheDestinationIsRefusedNamingThePathWithoutLitter()
        {
            string folder = Path.Combine(dir, "f");
            Directory.CreateDirectory(folder);
            var e = Assert.Throws<IOException>(() => AtomicFile.WriteAllText(folder, "x"));
            Assert.That(e.Message, Is.EqualTo(folder + ": is a folder"));
            Assert.That(Directory.GetFileSystemEntries(dir), Is.EqualTo(new[] { folder }));
            Assert.That(Directory.GetFileSystemEntries(folder), Is.Empty);
        }

        [Test]
        public void TheTemporaryFileIsNextToItsDestinationUnderTheNameTheCleanupRemoves()
        {
            string sub = Path.Combine(dir, "sub");
            Directory.CreateDirectory(sub);
            string path = Path.Combine(sub, "a.csv");
            string seen = null;
            AtomicFile.WriteWith(path, temp => { seen = temp; File.WriteAllText(temp, "x"); });
            Assert.That(Path.GetDirectoryName(seen), Is.EqualTo(sub), "in the destination's own folder (one file system)");
            Assert.That(AtomicFile.IsTemporaryName(Path.GetFileName(seen)), Is.True, Path.GetFileName(seen));
            Assert.That(AtomicFile.IsTemporaryName(Path.GetFileName(AtomicFile.TemporaryPath(sub))), Is.True);
            Assert.That(File.ReadAllText(path), Is.EqualTo("x"));
        }

        [Test]
        public void WriteWithOpensItsWritersFileToSyncItUnlessToldTheWriterSyncedIt()
        {
            // A writer that leaves a folder where its file should be shows whether the file is opened to be synced:
            // opening it fails (access refused), while the rename without that open fails on a missing source file.
            Action<string> folderInstead = temp => Directory.CreateDirectory(temp);
            Assert.Throws<UnauthorizedAccessException>(() => AtomicFile.WriteWith(Path.Combine(dir, "a.csv"), folderInstead), "WriteWith syncs the file");
            Assert.Throws<UnauthorizedAccessException>(() => AtomicFile.Write(Path.Combine(dir, "b.csv"), false, folderInstead));
            Assert.Throws<FileNotFoundException>(() => AtomicFile.Write(Path.Combine(dir, "c.csv"), true, folderInstead), "synced by its writer: not opened again");
            AtomicFile.Durable = false;
            Assert.Throws<FileNotFoundException>(() => AtomicFile.WriteWith(Path.Combine(dir, "d.csv"), folderInstead), "not durable: not synced");
        }

        [Test]
        public void CreateDirectoryOfNothingDoesNothing()
        {
            Assert.DoesNotThrow(() => AtomicFile.CreateDirectory(""));
            Assert.DoesNotThrow(() => AtomicFile.CreateDirectory(null));
        }

        [Test]
        public void CreateDirectorySyncsTheFolderAboveTheOneItCreatesAndNothingForOneThatExists()
        {
            RequireLinux("the folder sync's outcome");
            // /proc refuses fsync on a folder (EINVAL): DirectorySync then reads Refused, so what the next call syncs shows.
            AtomicFile.SyncDirectory("/proc");
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Refused), "no exception: a refusal is not an error");

            string made = Path.Combine(dir, "new");
            AtomicFile.CreateDirectory(made);
            Assert.That(Directory.Exists(made), Is.True);
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Synced), "the folder above the new one is synced");

            // A folder that exists is left alone: nothing above it is synced (/proc would say Refused).
            AtomicFile.CreateDirectory("/proc/sys/kernel");
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Synced));

            // Not durable: nothing synced.
            AtomicFile.SyncDirectory("/proc");
            AtomicFile.Durable = false;
            AtomicFile.CreateDirectory(Path.Combine(dir, "fast"));
            Assert.That(Directory.Exists(Path.Combine(dir, "fast")), Is.True);
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Refused), "not durable: no folder synced");
        }

        [Test]
        public void OnLinuxAFolderIsSyncedAndAMissingOneIsAnErrorNamingItAndItsErrno()
        {
            RequireLinux("libc's open/fsync");
            AtomicFile.SyncDirectory("/proc");
            AtomicFile.SyncDirectory(dir);
            Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Synced));
            string missing = Path.Combine(dir, "missing");
            var e = Assert.Throws<IOException>(() => AtomicFile.SyncDirectory(missing));
            Assert.That(e.Message, Is.EqualTo(missing + ": the folder could not be opened to sync it (errno 2)"), "ENOENT");
        }

        [Test]
        public void SyncingAFolderLeavesNoDescriptorOpen()
        {
            RequireLinux("/proc/self/fd");
            AtomicFile.SyncDirectory(dir);
            int before = Directory.GetFileSystemEntries("/proc/self/fd").Length;
            for (int i = 0; i < 200; i++) AtomicFile.SyncDirectory(dir);
            AtomicFile.SyncDirectory("/proc"); // refused: closed too
            int after = Directory.GetFileSystemEntries("/proc/self/fd").Length;
            Assert.That(after - before, Is.LessThan(50), "descriptors left open by 201 folder syncs (other threads may open a few)");
        }

        [Test]
        public void TheCleanupLeavesALinkToAFolderNamedLikeATemporaryFile()
        {
            RequireLinux("symbolic links made with ln");
            Directory.CreateDirectory(Path.Combine(dir, "target"));
            string link = Path.Combine(dir, ".ph0123abcd.tmp");
            using (var ln = System.Diagnostics.Process.Start(new System.Diagnostics.ProcessStartInfo("ln", "-s target " + link) { UseShellExecute = false }))
            {
                ln.WaitForExit();
                if (ln.ExitCode != 0) Assert.Ignore("ln -s failed");
            }
            File.WriteAllText(Path.Combine(dir, ".ph4567abcd.tmp"), "half");
            Assert.That(AtomicFile.RemoveStaleTemporaries(dir), Is.EqualTo(1), "only the file; a folder (through a link) is not a temporary file");
            Assert.That(Directory.Exists(link), Is.True);
        }

        [Test]
        public void ARenameIntoAMissingFolderGivesUpWithItsError()
        {
            string temp = AtomicFile.TemporaryPath(dir);
            File.WriteAllText(temp, "x");
            string target = Path.Combine(dir, "missing", "a.csv");
            Exception thrown = null;
            var run = Task.Run(() =>
            {
                try { AtomicFile.Rename(temp, target); }
                catch (Exception e) { thrown = e; }
            });
            Assert.That(run.Wait(10000), Is.True, "the rename gives up after a few attempts (it looped)");
            Assert.That(thrown, Is.InstanceOf<DirectoryNotFoundException>());
            Assert.That(File.ReadAllText(temp), Is.EqualTo("x"), "the temporary file is left to its writer");
        }

        [Test]
        public void RacingWritersOfOneNewFileAllSucceed()
        {
            // The destination appears (or is replaced) between the writer's check and its rename: the rename tries again.
            AtomicFile.Durable = false; // many rounds, quickly; the syncs play no part in the race
            for (int round = 0; round < 200; round++)
            {
                string path = Path.Combine(dir, "r" + round + ".csv");
                var errors = new List<Exception>();
                var threads = new List<Thread>();
                using (var go = new ManualResetEventSlim(false))
                {
                    for (int k = 0; k < 6; k++)
                    {
                        int writer = k;
                        threads.Add(new Thread(() =>
                        {
                            go.Wait(); // all at once: the race this is about
                            try { AtomicFile.WriteAllText(path, "writer " + writer); }
                            catch (Exception e) { lock (errors) errors.Add(e); }
                        }));
                    }
                    foreach (var t in threads) t.Start();
                    go.Set();
                    foreach (var t in threads) t.Join();
                }
                Assert.That(errors, Is.Empty, "round " + round);
                Assert.That(File.ReadAllText(path), Does.StartWith("writer "));
            }
            foreach (string f in Directory.GetFiles(dir)) Assert.That(Path.GetFileName(f), Does.Not.StartWith(".ph"));
        }
    }
}
