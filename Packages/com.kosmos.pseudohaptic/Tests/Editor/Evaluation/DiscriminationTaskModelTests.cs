using System;
using System.Linq;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>The headset discrimination task's decisions without the engine: settings, begin, sides, answers, errors, the text shown.</summary>
    public class DiscriminationTaskModelTests
    {
        TempFolder _folder;
        string TrialsFile => _folder.File("trials.csv");

        [SetUp]
        public void CreateFolder() => _folder = new TempFolder("ph-2afc-task-");

        [TearDown]
        public void DeleteFolder() => _folder.Dispose();

        static DiscriminationSettings Settings(DiscriminationProcedure procedure = DiscriminationProcedure.ConstantStimuli) => new DiscriminationSettings
        {
            Procedure = procedure, StandardKg = 0.5, Seed = 7,
            ComparisonKg = new[] { 0.4, 0.5, 0.6 }, Repetitions = 2, CatchKg = new[] { 1.0 }, CatchRepetitions = 1,
            StaircaseStartKg = 0.7, StaircaseStepKg = 0.08, HalvingReversals = 2, MinStepKg = 0.01,
            StopAfterReversals = 6, LastReversals = 4, MaxTrials = 40,
        };

        [Test]
        public void TheTrialsFileIsTakenUnderThePackagesFolderUnlessRooted()
        {
            string data = _folder.File("data");
            Assert.That(DiscriminationTaskModel.TrialsPath("", data), Is.EqualTo(Path.Combine(data, "Kosmos.PseudoHaptic", "trials.csv")));
            Assert.That(DiscriminationTaskModel.TrialsPath(null, data), Is.EqualTo(Path.Combine(data, "Kosmos.PseudoHaptic", "trials.csv")));
            Assert.That(DiscriminationTaskModel.TrialsPath("p1.csv", data), Is.EqualTo(Path.Combine(data, "Kosmos.PseudoHaptic", "p1.csv")));
            Assert.That(DiscriminationTaskModel.TrialsPath(TrialsFile, data), Is.EqualTo(TrialsFile));
        }

        [Test]
        public void SettingsGiveThePlanOrTheStaircaseTheyName()
        {
            var plan = Settings().PlanFor("P1", "on").Build("P1", "on");
            Assert.That(plan.Count, Is.EqualTo(3 * 2 + 1));
            Assert.That(Settings().PlanFor("P1", "on").Seed, Is.EqualTo(DiscriminationSettings.SessionSeed(Settings().Seed, "P1", "on")));
            var session = Settings().CreateSession("P1", "on", TrialsFile);
            Assert.That(session.Staircase, Is.Null);
            Assert.That(session.Plan.Count, Is.EqualTo(plan.Count));
            for (int i = 0; i < plan.Count; i++)
            {
                Assert.That(session.Plan[i].Comparison, Is.EqualTo(plan[i].Comparison));
                Assert.That(session.Plan[i].ComparisonFirst, Is.EqualTo(plan[i].ComparisonFirst));
            }

            Assert.That(Settings(DiscriminationProcedure.Staircase1Up2Down).MakeStaircase("P1", "").Down, Is.EqualTo(2));
            var three = Settings(DiscriminationProcedure.Staircase1Up3Down).CreateSession("P1", "", TrialsFile);
            Assert.That(three.Plan, Is.Null);
            Assert.That(three.Staircase.Down, Is.EqualTo(3));
            Assert.That(three.Staircase.Start, Is.EqualTo(0.7));
            Assert.That(three.Staircase.MaxTrials, Is.EqualTo(40));
            Assert.That(three.Staircase.MinLevel, Is.EqualTo(0.001));
        }

        /// <summary>
        /// One study seed, an order per participant and condition: the same trials (levels, repetitions, counterbalancing)
        /// in another order for each, and the same order again for the same participant and condition (a resume rebuilds it).
        /// </summary>
        [Test]
        public void EachParticipantAndConditionRunsInItsOwnOrderFromTheStudySeed()
        {
            var settings = Settings();
            settings.ComparisonKg = new[] { 0.35, 0.4, 0.45, 0.55, 0.6, 0.65 };
            settings.Repetitions = 8;
            settings.CatchRepetitions = 2; // even counts: the sides are counterbalanced exactly, not drawn
            string Order(string participant, string condition) => string.Join(" ", settings.PlanFor(participant, condition).Build(participant, condition)
                .Select(t => t.Comparison.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + (t.ComparisonFirst ? "c" : "s")));
            string Multiset(string participant, string condition) => string.Join(" ", Order(participant, condition).Split(' ').OrderBy(x => x, StringComparer.Ordinal));
            var orders = new HashSet<string>();
            for (int p = 1; p <= 200; p++)
                foreach (string condition in new[] { "visual", "pseudo-haptic" })
                {
                    Assert.That(Order("P" + p, condition), Is.EqualTo(Order("P" + p, condition)), "rebuilt, the same order");
                    Assert.That(Multiset("P" + p, condition), Is.EqualTo(Multiset("P1", "visual")), "the same trials");
                    orders.Add(Order("P" + p, condition));
                }
            Assert.That(orders, Has.Count.EqualTo(400), "400 sessions, 400 orders");
            Assert.That(DiscriminationSettings.SessionSeed(1, "P1", "0"), Is.Not.EqualTo(DiscriminationSettings.SessionSeed(1, "P", "10")), "names are not run together");
            Assert.That(DiscriminationSettings.SessionSeed(1, "P1", ""), Is.Not.EqualTo(DiscriminationSettings.SessionSeed(2, "P1", "")), "another study seed, another order");
            // Pinned: the same on every runtime (FNV-1a, no string.GetHashCode): a file begun on one device resumes on another.
            // The value from the definition, computed apart (Python: FNV-1a 64 over "P1" then "on", each closed by its length, XOR 1 × 0x9E3779B97F4A7C15).
            Assert.That(DiscriminationSettings.SessionSeed(1, "P1", "on"), Is.EqualTo(2516963643970286428L));
        }

        [Test]
        public void NoCatchMassesGiveNoCatchLevels()
        {
            var none = Settings();
            none.CatchKg = null;
            Assert.That(none.Plan().CatchLevels, Is.Empty);
        }

        [Test]
        public void BeginRefusesMissingObjectsAndBadSettingsWithAReason()
        {
            var model = new DiscriminationTaskModel();
            var failures = new List<string>();
            model.Failed += failures.Add;
            Assert.That(model.DisplayText(), Is.EqualTo(DiscriminationTaskModel.WaitingText));

            Assert.That(model.Begin(false, Settings(), "P1", "", TrialsFile), Is.False);
            Assert.That(model.Error, Is.EqualTo("the left and right objects are not set"));
            Assert.That(model.DisplayText(), Is.EqualTo(model.Error));

            Assert.That(model.Begin(true, Settings(), " P1", "", TrialsFile), Is.False);
            Assert.That(model.Session, Is.Null);
            Assert.That(model.Error, Does.Contain("surrounding spaces"));

            File.WriteAllText(TrialsFile, "participant,standard\nP1,0.5\n");
            Assert.That(model.Begin(true, Settings(), "P1", "", TrialsFile), Is.False, "a file psychometric would refuse");
            Assert.That(model.Error, Does.Contain("trials.csv"));
            Assert.That(failures.Count, Is.EqualTo(3));

            File.Delete(TrialsFile);
            Assert.That(model.Begin(true, Settings(), "P1", "", TrialsFile), Is.True);
            Assert.That(model.Error, Is.Null);
            Assert.That(model.HasTrial, Is.True);
        }

        [Test]
        public void LiftsAreNotedBySideAndOthersIgnored()
        {
            var model = new DiscriminationTaskModel();
            Assert.That(model.NoteLift(true, false), Is.False, "no session yet");
            model.Begin(true, Settings(), "P1", "", TrialsFile);
            Assert.That(model.NoteLift(false, false), Is.False, "another object");
            Assert.That(model.DisplayText(), Does.EndWith(DiscriminationTaskModel.LiftText));
            Assert.That(model.NoteLift(false, true), Is.True);
            Assert.That(model.Session.WasLifted(PairSide.Right), Is.True);
            Assert.That(model.Session.WasLifted(PairSide.Left), Is.False);
            Assert.That(model.DisplayText(), Is.EqualTo("Trial 1 / 7\n" + DiscriminationTaskModel.LiftText + " (right: done)"));
            Assert.That(model.NoteLift(true, false), Is.True);
            Assert.That(model.DisplayText(), Is.EqualTo("Trial 1 / 7\n" + DiscriminationTaskModel.AnswerText));

            var leftFirst = new DiscriminationTaskModel();
            leftFirst.Begin(true, Settings(), "P2", "", TrialsFile);
            Assert.That(leftFirst.NoteLift(true, false), Is.True);
            Assert.That(leftFirst.DisplayText(), Is.EqualTo("Trial 1 / 7\n" + DiscriminationTaskModel.LiftText + " (left: done)"));
        }

        [Test]
        public void AnAnswerIsTakenOnlyWithBothLiftedAndBothPutDown()
        {
            var model = new DiscriminationTaskModel();
            Assert.That(model.Answer(PairSide.Left, false), Is.False, "no session");
            model.Begin(true, Settings(), "P1", "", TrialsFile);
            Assert.That(model.Answer(PairSide.Left, false), Is.False, "nothing lifted");
            model.NoteLift(true, false);
            model.NoteLift(false, true);
            Assert.That(model.Answer(PairSide.Left, true), Is.False, "an object is still held");
            Assert.That(File.Exists(TrialsFile), Is.False);

            var trial = model.Session.Current;
            Assert.That(model.Answer(PairSide.Left, false), Is.True);
            Assert.That(trial.Response, Is.EqualTo(trial.ComparisonFirst ? 1 : 0), "left is the comparison when it is first");
            Assert.That(File.ReadAllText(TrialsFile), Does.StartWith(TrialsCsv.Header + "\n"));
            Assert.That(model.Session.AnsweredCount, Is.EqualTo(1));
            Assert.That(model.DisplayText(), Does.StartWith("Trial 2 / 7\n"));
        }

        [Test]
        public void AllAnsweredShowsDoneAndAResumedSessionContinues()
        {
            var model = new DiscriminationTaskModel();
            model.Begin(true, Settings(), "P1", "", TrialsFile);
            for (int i = 0; i < 3; i++)
            {
                model.NoteLift(true, false);
                model.NoteLift(false, true);
                Assert.That(model.Answer(PairSide.Right, false), Is.True);
            }
            var again = new DiscriminationTaskModel();
            Assert.That(again.Begin(true, Settings(), "P1", "", TrialsFile), Is.True);
            Assert.That(again.Session.ResumedCount, Is.EqualTo(3));
            Assert.That(again.DisplayText(), Does.StartWith("Trial 4 / 7\n"));
            for (int i = 3; i < 7; i++)
            {
                again.NoteLift(true, false);
                again.NoteLift(false, true);
                Assert.That(again.Answer(PairSide.Left, false), Is.True);
            }
            Assert.That(again.HasTrial, Is.False);
            Assert.That(again.DisplayText(), Is.EqualTo(DiscriminationTaskModel.DoneText));
            Assert.That(again.Answer(PairSide.Left, false), Is.False);
        }

        [Test]
        public void AnAnswerThatCannotBeSavedSaysSoIsKeptAndIsSavedOnceByTheRetry()
        {
            double now = 0;
            var model = new DiscriminationTaskModel(saver: new SaveQueue(background: false, retrySeconds: 2, clock: () => now));
            string path = _folder.File("taken");
            model.Begin(true, Settings(), "P1", "", path);
            Directory.CreateDirectory(path); // a folder where the file should go: the write fails
            model.NoteLift(true, false);
            model.NoteLift(false, true);
            string failed = null;
            int saved = 0;
            model.Failed += e => failed = e;
            model.Saved += () => saved++;
            Assert.That(model.Answer(PairSide.Left, false), Is.False);
            Assert.That(model.Error, Does.StartWith(DiscriminationTaskModel.NotSavedPrefix));
            Assert.That(model.Error, Does.EndWith(" (the answer is kept and saved as soon as it can be)"));
            Assert.That(failed, Is.EqualTo(model.Error));
            Assert.That(model.DisplayText(), Is.EqualTo(model.Error));
            Assert.That(model.Session.AnsweredCount, Is.Zero, "not acknowledged");
            Assert.That(model.IsSaving, Is.True, "kept in memory");
            Assert.That(model.Answer(PairSide.Right, false), Is.False, "no other answer while it is unsaved");
            Directory.Delete(path);
            now = 1.9;
            Assert.That(model.Update(), Is.False, "not tried again before its delay");
            Assert.That(File.Exists(path), Is.False);
            now = 2.0;
            Assert.That(model.Update(), Is.True, "the retry saved it");
            Assert.That(model.Error, Is.Null);
            Assert.That(saved, Is.EqualTo(1));
            Assert.That(model.Session.AnsweredCount, Is.EqualTo(1));
            Assert.That(model.Session.CurrentIndex, Is.EqualTo(1), "the next trial is shown");
            string[] lines = File.ReadAllLines(path);
            Assert.That(lines, Has.Length.EqualTo(2), "the header and the one answer, once");
            Assert.That(lines[1].Split(',')[2], Is.EqualTo("1"));
            now = 10;
            Assert.That(model.Update(), Is.False);
            Assert.That(model.Saver.Writes, Is.EqualTo(1), "a saved answer is not written again");
            Assert.That(model.Saver.Failures, Is.EqualTo(1));
        }

        [Test]
        public void InAQueueSharedWithAnotherFileAFailedWriteOfThatFileHoldsTheAnswerButNotTheBegin()
        {
            // One writer for a study's files (SaveQueue): the questionnaire's file fails to write first. Order holds, so
            // the task's answer waits behind it, shown as being saved; a Begin is held only by the task's own answer.
            double now = 0;
            bool diskFull = true, otherSaved = false;
            var saver = new SaveQueue(background: false, retrySeconds: 2, clock: () => now);
            saver.Enqueue(() => { if (diskFull) throw new IOException("the questionnaire's file: disk full"); }, () => otherSaved = true, e => { });
            saver.Pump();
            Assert.That(saver.LastError, Is.Not.Null);
            var model = new DiscriminationTaskModel(saver: saver);
            Assert.That(model.Begin(true, Settings(), "P1", "", TrialsFile), Is.True, "another file's unsaved write does not hold the task");
            model.NoteLift(true, false);
            model.NoteLift(false, true);
            Assert.That(model.Answer(PairSide.Left, false), Is.True, "taken, and queued");
            Assert.That(model.IsSaving, Is.True);
            Assert.That(model.DisplayText(), Is.EqualTo("Trial 1 / 7\n" + DiscriminationTaskModel.SavingText));
            Assert.That(File.Exists(TrialsFile), Is.False, "nothing is written after a failed write");

            Assert.That(model.Begin(true, Settings(), "P2", "", TrialsFile), Is.False, "the answer is not saved yet");
            Assert.That(model.Error, Is.EqualTo("the last answer is not saved yet: " + saver.LastError));
            Assert.That(model.Session.Participant, Is.EqualTo("P1"));

            diskFull = false;
            now = 2;
            Assert.That(model.Update(), Is.True);
            Assert.That(otherSaved, Is.True);
            Assert.That(model.Session.AnsweredCount, Is.EqualTo(1));
            Assert.That(model.Error, Is.Null);
            Assert.That(model.Begin(true, Settings(), "P2", "", TrialsFile), Is.True);
            Assert.That(model.Session.Participant, Is.EqualTo("P2"));
        }

        [Test]
        public void APokeWithinTheCooldownDoesNotAnswerAgain()
        {
            var model = new DiscriminationTaskModel(cooldown: 0.5, releaseTime: 0.1);
            Assert.That(model.Touch(10.0), Is.True);
            model.Stay(10.05);
            Assert.That(model.Touch(10.3), Is.False, "within the cooldown");
            Assert.That(model.Touch(11.0), Is.True);
        }
    }
}
