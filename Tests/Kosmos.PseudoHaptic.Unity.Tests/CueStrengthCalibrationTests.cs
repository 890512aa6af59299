using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Samples;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 31, the glue under the double: the calibration sample's cue-strength staircase runs at the default strength,
    /// stores the tuned strength beside the user's standard speed, and every weight of that user then applies it.
    /// </summary>
    public sealed class CueStrengthCalibrationTests
    {
        string _folder;

        [SetUp]
        public void UseTemporaryStore()
        {
            _folder = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-cue-" + System.Guid.NewGuid().ToString("N"));
            UserCalibrationStore.SetRootForTests(_folder);
        }

        [TearDown]
        public void RemoveTemporaryStore()
        {
            UserCalibrationStore.SetRootForTests(null);
            if (Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        [Test]
        public void TheStaircaseRunsAtTheDefaultStrengthAndItsStrengthIsStoredAndApplied()
        {
            // The user has a standard speed from the golf-ball lifts and an old strength, which the staircase must not render.
            UserCalibrationStore.Save(UserCalibration.From(UserCalibrationStore.CurrentUserId, new CalibrationResult(true, 0.62, 5, 5, 0.05, null)));
            UserCalibrationStore.SaveCueStrength(UserCalibrationStore.CurrentUserId, 2.5, 0.5);

            var root = new GameObject("Sample").transform;
            var handObject = new GameObject("Hand");
            handObject.transform.position = new Vector3(0.3f, 1.2f, 0.2f);
            var hand = handObject.AddComponent<TransformHandPoseSource>();
            SampleContent.CalibrationStation(root, hand);
            Frames.Run(2);
            var cue = GameObject.Find("Cue Strength Calibrator").GetComponent<CueStrengthCalibrator>();
            Assert.That(cue.Begin(), Is.True, cue.Error);
            DiscriminationTask task = cue.Task;

            // A participant who calls the comparison heavier from 2.5 kg up (a threshold half a kilogram above the standard).
            for (int trial = 0; trial < 100 && !task.Session.IsFinished; trial++)
            {
                foreach (PseudoHapticWeight ball in PseudoHapticWeight.Enabled)
                {
                    Assert.That(ball.BeginHold(ball.transform.position), Is.True, ball.ConfigurationError);
                    Assert.That(ball.CueStrength, Is.EqualTo(1.0), "the staircase renders the default strength");
                    ball.EndHold();
                }
                double left = task.Session.MassAt(PairSide.Left), right = task.Session.MassAt(PairSide.Right);
                double comparison = task.Session.Current.Comparison;
                bool comparisonHeavier = comparison >= 2.5;
                bool comparisonLeft = left == comparison && right != comparison || (left == right && task.Session.Current.ComparisonFirst);
                PairSide heavier = comparisonHeavier == comparisonLeft ? PairSide.Left : PairSide.Right;
                Assert.That(task.Answer(heavier), Is.True, task.Error);
                // The answer is written off the main thread; the next trial comes when the write has returned (on a
                // loaded machine not within the same call): wait for it, as the task does on a pause.
                Assert.That(task.WaitForSaves(), Is.True, task.Error);
                task.Model.Update();
            }
            Assert.That(task.Session.IsFinished, Is.True);
            cue.Tick();
            Assert.That(cue.Result, Is.Not.Null, cue.Error);

            // What is stored is the engine-free step's tuning of that staircase, beside the standard speed.
            var expected = CueStrengthStep.Tune(task.Session.Staircase, CueStrengthTuning.ExperimentOneBoxes, 0.62, out _);
            Assert.That(UserCalibrationStore.TryLoad(UserCalibrationStore.CurrentUserId, out UserCalibration stored, out string error), Is.True, error);
            Assert.That(stored.format, Is.EqualTo(UserCalibration.CurrentFormat));
            Assert.That(stored.standardSpeed, Is.EqualTo(0.62));
            Assert.That(stored.cueStrength, Is.EqualTo(expected.CueStrength));
            Assert.That(stored.cueStrength, Is.Not.EqualTo(2.5));

            // A weight of this user applies it; one told not to stays at 1.
            var box = new GameObject("Box");
            box.transform.position = new Vector3(0, 1, 0.5f);
            box.AddComponent<BoxCollider>();
            var weight = box.AddComponent<PseudoHapticWeight>();
            weight.Mass = MassSource.Explicit;
            weight.ExplicitMassKg = 2;
            Assert.That(weight.Configure(), Is.True, weight.ConfigurationError);
            Assert.That(weight.CueStrength, Is.EqualTo(stored.cueStrength));
            weight.UserCueStrength = false;
            Assert.That(weight.Configure(), Is.True, weight.ConfigurationError);
            Assert.That(weight.CueStrength, Is.EqualTo(1.0));
        }
    

        /// <summary>Rest 0.8 s, lift 0.3 m in <paramref name="durations"/>[i] s (minimum jerk), hold 0.6 s, lower in 0.6 s, per lift.</summary>
        static double GolfBallHeight(double t, double rest, double[] durations)
        {
            foreach (double duration in durations)
            {
                double length = 0.8 + duration + 0.6 + 0.6;
                if (t < length)
                {
                    if (t < 0.8) return rest;
                    if (t < 0.8 + duration) return rest + 0.3 * MinimumJerk((t - 0.8) / duration);
                    if (t < 1.4 + duration) return rest + 0.3;
                    return rest + 0.3 * (1 - MinimumJerk((t - 1.4 - duration) / 0.6));
                }
                t -= length;
            }
            return rest;
        }

        static double MinimumJerk(double u) { u = System.Math.Max(0, System.Math.Min(1, u)); return u * u * u * (10 - 15 * u + 6 * u * u); }

        /// <summary>The calibration sample with a hand that makes <paramref name="durations"/>' golf-ball lifts, frame by frame
        /// through Update (nothing called on the cue-strength calibrator).</summary>
        static (StandardSpeedCalibrator speed, CueStrengthCalibrator cue) LiftTheGolfBall(double[] durations)
        {
            var root = new GameObject("Sample").transform;
            var handObject = new GameObject("Hand");
            const float rest = 0.8f;
            handObject.transform.position = new Vector3(0, rest, 0.45f);
            var hand = handObject.AddComponent<TransformHandPoseSource>();
            StandardSpeedCalibrator speed = SampleContent.CalibrationStation(root, hand);
            speed.LiftsWanted = durations.Length;
            var cue = GameObject.Find("Cue Strength Calibrator").GetComponent<CueStrengthCalibrator>();
            Frames.Run(1);
            double seconds = 0;
            foreach (double d in durations) seconds += 0.8 + d + 1.2;
            for (double t = 0; t < seconds + 1; t += Frames.DefaultDuration)
            {
                handObject.transform.position = new Vector3(0, (float)GolfBallHeight(t, rest, durations), 0.45f);
                Frames.Run(1);
            }
            return (speed, cue);
        }

        [Test]
        public void AcceptedGolfBallLiftsStartTheStaircaseByThemselves()
        {
            var (speed, cue) = LiftTheGolfBall(new[] { 0.50, 0.55, 0.48 });
            Assert.That(speed.CurrentPhase, Is.EqualTo(CalibrationPhase.Accepted), speed.Message);
            Assert.That(cue.IsRunning, Is.True, "the staircase began when the lifts were accepted: " + cue.Error);
            Assert.That(cue.Task.Session, Is.Not.Null);
            Assert.That(cue.Task.Session.Staircase, Is.Not.Null, "the cue-strength step's 1-up-2-down staircase");
            Assert.That(cue.Task.Session.IsFinished, Is.False);
            Assert.That(cue.Task.Condition, Is.EqualTo(CueStrengthStep.Condition));
        }

        [Test]
        public void RejectedGolfBallLiftsDoNotStartIt()
        {
            // Wildly inconsistent paces (0.25, 0.6 and 2 s for the same 0.3 m): the station rejects them.
            var (speed, cue) = LiftTheGolfBall(new[] { 0.25, 0.6, 2.0 });
            Assert.That(speed.CurrentPhase, Is.EqualTo(CalibrationPhase.Rejected), speed.Message);
            Assert.That(cue.IsRunning, Is.False);
            Assert.That(cue.Task.Session == null || cue.Task.Session.Staircase == null, Is.True, "no staircase was begun");
        }

        [Test]
        public void APaperLiteralPresetRunsThePaperAsPrinted()
        {
            var box = new GameObject("Box");
            box.transform.position = new Vector3(0, 1, 0.5f);
            box.AddComponent<BoxCollider>();
            var weight = box.AddComponent<PseudoHapticWeight>();
            weight.Mass = MassSource.Explicit;
            weight.ExplicitMassKg = 2;
            weight.Profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperLiteralName);
            Assert.That(weight.BeginHold(box.transform.position), Is.True, weight.ConfigurationError);
            Assert.That(weight.Hold.Literal, Is.Not.Null, "the preset's asset is run by PaperLiteralSolver");
            var literal = new PaperLiteralSolver(2);
            literal.BeginHold(1, 1);
            for (int i = 1; i <= 90; i++)
            {
                var hand = new Vector3(0, 1 + 0.3f * i / 90f, 0.5f);
                float y = weight.Step(hand, true, true, double.NaN, 1 / 90f);
                double expected = literal.Step(hand.y, true, 1 / 90f);
                Assert.That(y, Is.EqualTo((float)expected).Within(1e-5f), "frame " + i);
            }
            Assert.That(weight.Offset, Is.GreaterThan(0.1), "2 kg lags the hand, as printed");
        }
    }
}
