using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The temporary files a kill or a power cut leaves behind (a write stopped between its temporary file and the
    /// rename) are removed when a study session starts or resumes in their folder: exactly AtomicFile's own
    /// temporary names (".ph" + 8 lowercase hex digits + ".tmp"), nothing else, and never one being written now.
    /// </summary>
    public class StaleTemporaryTests
    {
        string dir;

        // Names that look like a temporary file and are not AtomicFile's: the CLI's outputs (other extension), other
        // programs' .tmp files, too few / too many / upper-case / non-hex digits, no leading dot. (No two differ only in
        // case, so that they are distinct files on a case-insensitive file system too.)
        static readonly string[] NotOurs =
        {
            ".ph12345678.csv", "notes.tmp", ".phXYZ.tmp", ".ph0123ABCD.tmp", ".ph0123abc.tmp", ".ph0123abcde.tmp",
            ".ph0123abcg.tmp", "ph0123abcd.tmp", ".ph0123abcd.tmp.bak", ".ph4567abcd.TMP", ".pH89abcdef.tmp", "trials.csv",
        };

        [SetUp]
        public void SetUp()
        {
            dir = Path.Combine(Path.GetTempPath(), "ph-stale-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
        }

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(dir)) Directory.Delete(dir, true);
        }

        void Put(string name, string text = "x") => File.WriteAllText(Path.Combine(dir, name), text);

        string[] Names()
        {
            var names = new List<string>();
            foreach (string f in Directory.GetFileSystemEntries(dir)) names.Add(Path.GetFileName(f));
            names.Sort(StringComparer.Ordinal);
            return names.ToArray();
        }

        static string[] Sorted(IEnumerable<string> names)
        {
            var list = new List<string>(names);
            list.Sort(StringComparer.Ordinal);
            return list.ToArray();
        }

        [Test]
        public void OnlyFilesNamedExactlyLikeAtomicFilesTemporariesAreRemoved()
        {
            Put(".ph9876fedc.tmp", "half an answer");
            Put(".phdeadbeef.tmp", "");
            foreach (string name in NotOurs) Put(name, "keep " + name);
            Directory.CreateDirectory(Path.Combine(dir, ".ph00c0ffee.tmp"));        // a folder of that name stays
            Directory.CreateDirectory(Path.Combine(dir, "sub"));
            File.WriteAllText(Path.Combine(dir, "sub", ".ph0badcafe.tmp"), "x");    // only this folder, not below

            Assert.That(AtomicFile.RemoveStaleTemporaries(dir), Is.EqualTo(2));

            var expected = new List<string>(NotOurs) { ".ph00c0ffee.tmp", "sub" };
            Assert.That(Names(), Is.EqualTo(Sorted(expected)));
            foreach (string name in NotOurs) Assert.That(File.ReadAllText(Path.Combine(dir, name)), Is.EqualTo("keep " + name), name);
            Assert.That(File.Exists(Path.Combine(dir, "sub", ".ph0badcafe.tmp")), Is.True);
            Assert.That(AtomicFile.RemoveStaleTemporaries(dir), Is.Zero, "nothing left to remove");
        }

        [Test]
        public void TheNamePatternIsExactlyTheOneTheWriterUses()
        {
            // Every name the writer makes matches; the same name with the CLI's extensions does not.
            var pattern = new Regex("^\\.ph[0-9a-f]{8}\\.tmp$");
            for (int i = 0; i < 200; i++)
            {
                string name = Path.GetFileName(AtomicFile.TemporaryPath(dir));
                Assert.That(pattern.IsMatch(name), Is.True, name + " (the writer's own name changed: the cleanup must follow it)");
                Assert.That(AtomicFile.IsTemporaryName(name), Is.True, name);
                Assert.That(AtomicFile.IsTemporaryName(Path.GetFileName(AtomicFile.TemporaryPath(dir, ".csv"))), Is.False);
            }
            foreach (string name in NotOurs) Assert.That(AtomicFile.IsTemporaryName(name), Is.False, name);
            Assert.That(AtomicFile.IsTemporaryName(null), Is.False);
            Assert.That(AtomicFile.IsTemporaryName(""), Is.False);
        }

        [Test]
        public void ATemporaryFileBeingWrittenNowIsLeftAlone()
        {
            // Another writer of the same app (the panel beside the task, each with its own queue) may be between its
            // temporary file and its rename when a session begins in the folder.
            string path = Path.Combine(dir, "trials.csv");
            int removedMeanwhile = -1;
            string seen = null;
            AtomicFile.WriteWith(path, temp =>
            {
                seen = temp;
                File.WriteAllText(temp, "the answer");
                removedMeanwhile = AtomicFile.RemoveStaleTemporaries(dir);
                Assert.That(File.Exists(temp), Is.True, "the write in progress keeps its temporary file");
            });
            Assert.That(AtomicFile.IsTemporaryName(Path.GetFileName(seen)), Is.True);
            Assert.That(removedMeanwhile, Is.Zero);
            Assert.That(File.ReadAllText(path), Is.EqualTo("the answer"));
            Put(Path.GetFileName(seen), "left by a kill"); // once that write is over, the same name is stale
            Assert.That(AtomicFile.RemoveStaleTemporaries(dir), Is.EqualTo(1));
            Assert.That(Names(), Is.EqualTo(new[] { "trials.csv" }));
        }

        [Test]
        public void AMissingOrEmptyFolderIsNothingToRemove()
        {
            Assert.That(AtomicFile.RemoveStaleTemporaries(Path.Combine(dir, "missing")), Is.Zero);
            Assert.That(AtomicFile.RemoveStaleTemporaries(""), Is.Zero);
            Assert.That(AtomicFile.RemoveStaleTemporaries(null), Is.Zero);
        }

        [Test]
        public void ADiscriminationSessionRemovesTheLeftoversInItsFolderWhenItBeginsOrResumes()
        {
            string path = Path.Combine(dir, "trials.csv");
            var plan = new ConstantStimuliPlan { Standard = 0.5, Levels = new[] { 0.4, 0.6 }, Repetitions = 1, Seed = 3 };
            Put(".ph11111111.tmp");
            Put(".ph12345678.csv");
            var first = new DiscriminationSession("P1", "on", path, plan);
            Assert.That(first.RemovedTemporaries, Is.EqualTo(1));
            first.NoteLift(PairSide.Left);
            first.NoteLift(PairSide.Right);
            Assert.That(first.Answer(PairSide.Left), Is.True);

            Put(".ph22222222.tmp"); // a kill during the next write
            var resumed = new DiscriminationSession("P1", "on", path, plan);
            Assert.That(resumed.RemovedTemporaries, Is.EqualTo(1));
            Assert.That(resumed.ResumedCount, Is.EqualTo(1));
            Assert.That(Names(), Is.EqualTo(new[] { ".ph12345678.csv", "trials.csv" }));
        }

        [Test]
        public void AQuestionnaireSessionRemovesTheLeftoversInItsFolderWhenItBeginsOrResumes()
        {
            string path = Path.Combine(dir, "responses.csv");
            Put(".phabcdef01.tmp");
            Put("notes.tmp");
            var session = new QuestionnaireSession(SampleQuestionnaires.Paper(), "P1", path);
            Assert.That(session.RemovedTemporaries, Is.EqualTo(1));
            Assert.That(Names(), Is.EqualTo(new[] { "notes.tmp" }));
        }
    }
}
