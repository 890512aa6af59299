using System.IO;
using NUnit.Framework;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>A scripted hand lifts a "golf ball" at the station; the calibration goes through the core and the store.</summary>
    public sealed class StandardSpeedCalibratorTests : PlayModeFixture
    {
        string _folder;

        [SetUp]
        public void UseTemporaryStore()
        {
            _folder = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-tests-" + System.Guid.NewGuid().ToString("N"));
            UserCalibrationStore.SetRootForTests(_folder);
        }

        [TearDown]
        public void RemoveTemporaryStore()
        {
            UserCalibrationStore.SetRootForTests(null);
            if (Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        StandardSpeedCalibrator Station(ScriptedHand hand, int lifts)
        {
            var go = Track(new GameObject("station"));
            go.SetActive(false); // ticked by the test
            var calibrator = go.AddComponent<StandardSpeedCalibrator>();
            calibrator.InjectHand(hand);
            calibrator.LiftsWanted = lifts;
            return calibrator;
        }

        /// <summary>Rest, lift <paramref name="rise"/> m in <paramref name="duration"/> s, hold, lower, as a person would.</summary>
        static void LiftOnce(StandardSpeedCalibrator c, ScriptedHand hand, Vector3 rest, float rise, float duration)
        {
            void Run(float seconds, System.Func<float, Vector3> path)
            {
                int n = Mathf.CeilToInt(seconds / FrameTime);
                for (int i = 1; i <= n; i++)
                {
                    hand.Track(path(i / (float)n), FrameTime);
                    c.Tick(FrameTime);
                }
            }
            Vector3 top = rest + new Vector3(0, rise, 0);
            Run(0.8f, u => rest);
            Run(duration, u => Vector3.Lerp(rest, top, (float)ScriptedHand.MinimumJerk(u)));
            Run(0.6f, u => top);
            Run(0.6f, u => Vector3.Lerp(top, rest, (float)ScriptedHand.MinimumJerk(u)));
        }

        [Test]
        public void FiveGolfBallLiftsGiveTheUsersStandardSpeedAndAreStored()
        {
            var rest = new Vector3(0, 0.8f, 0.4f);
            var hand = new ScriptedHand(rest);
            StandardSpeedCalibrator c = Station(hand, 5);
            CalibrationResult? completed = null;
            c.Completed += r => completed = r;
            c.Begin();
            float[] durations = { 0.50f, 0.55f, 0.48f, 0.52f, 0.50f };
            foreach (float d in durations) LiftOnce(c, hand, rest, 0.3f, d);

            Assert.That(c.CurrentPhase, Is.EqualTo(CalibrationPhase.Accepted), c.Message);
            Assert.That(completed.HasValue, Is.True);
            // 90 % of a 0.3 m minimum-jerk rise between 5 % and 95 % takes ~0.62 of the duration: ~0.87 m/s at 0.5 s.
            Assert.That(c.Result.StandardSpeed, Is.InRange(0.6, 1.2));
            Assert.That(c.Result.LiftsOffered, Is.EqualTo(5));
            Assert.That(c.Result.LiftsUsed, Is.GreaterThanOrEqualTo(3), "the core may drop an outlier");
            Assert.That(File.Exists(UserCalibrationStore.PathFor(UserCalibrationStore.CurrentUserId)), Is.True);
            Assert.That(UserCalibrationStore.StandardSpeedOrDefault, Is.EqualTo(c.Result.StandardSpeed));
        }

        [Test]
        public void LiftsThatAreTooSmallDoNotCountAndTheReasonIsShown()
        {
            var rest = new Vector3(0, 0.8f, 0.4f);
            var hand = new ScriptedHand(rest);
            StandardSpeedCalibrator c = Station(hand, 2);
            c.Begin();
            LiftOnce(c, hand, rest, 0.04f, 0.5f); // 4 cm is not a lift: the station waits for one, then gives up
            for (int i = 0; i < 600 && c.Measurements.Count == 0; i++)
            {
                hand.Track(rest, FrameTime);
                c.Tick(FrameTime);
            }
            Assert.That(c.Measurements.Count, Is.EqualTo(1));
            Assert.That(c.Measurements[0].IsAccepted, Is.False);
            Assert.That(c.Measurements[0].Reason, Does.Contain("too short"));
            Assert.That(c.Message, Does.Contain("did not count").And.Contain("too short"));
            Assert.That(c.CurrentPhase, Is.EqualTo(CalibrationPhase.Rest), "and asks for another lift");
        }

        [Test]
        public void WildlyInconsistentLiftsAreRejectedWithTheReason()
        {
            var rest = new Vector3(0, 0.8f, 0.4f);
            var hand = new ScriptedHand(rest);
            StandardSpeedCalibrator c = Station(hand, 3);
            c.Begin();
            LiftOnce(c, hand, rest, 0.3f, 0.25f); // ~1.7 m/s
            LiftOnce(c, hand, rest, 0.3f, 0.6f);  // ~0.7 m/s
            LiftOnce(c, hand, rest, 0.3f, 2.0f);  // ~0.2 m/s
            Assert.That(c.CurrentPhase, Is.EqualTo(CalibrationPhase.Rejected), c.Message);
            Assert.That(c.Message, Does.Contain("inconsistent"));
            Assert.That(File.Exists(UserCalibrationStore.PathFor(UserCalibrationStore.CurrentUserId)), Is.False);
        }
    }
}
