using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// What the tests of <see cref="AtomicFile"/>'s system calls share: a scratch folder per test, strace on this process
    /// (<see cref="SelfTrace"/>) reporting the calls under a path, and every switch a test turns (<see cref="AtomicFile.Durable"/>,
    /// the platform whose syncs are made) set back after it.
    /// </summary>
    public abstract class AtomicFileTracing
    {
        protected const string Syscalls = "fsync,fdatasync,rename,renameat,renameat2,mkdir,mkdirat";
        protected string _dir;

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "ph-syscalls-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void ResetAndDeleteFolder()
        {
            AtomicFile.Durable = true;
            AtomicFile.PlatformForTests = null;
            AtomicFile.ReplaceUnsupportedForTests = false;
            if (Directory.Exists(_dir)) Directory.Delete(_dir, true);
        }

        protected List<string> Traced(Action act, string under, string inject = null) => SelfTrace.CallsUnder(act, _dir, Syscalls, under, inject);

        /// <summary>The temporary file a traced write renamed from (the first rename's source).</summary>
        protected static string TemporaryOf(List<string> calls)
        {
            string rename = calls.First(c => c.StartsWith("rename ", StringComparison.Ordinal));
            string temp = rename.Substring(7, rename.IndexOf(" -> ", StringComparison.Ordinal) - 7);
            Assert.That(AtomicFile.IsTemporaryName(Path.GetFileName(temp)), Is.True, temp);
            return temp;
        }
    }
}
