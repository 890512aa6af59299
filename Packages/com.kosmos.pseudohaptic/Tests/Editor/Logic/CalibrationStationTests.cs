using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The calibration station's lift segmentation on a scripted Quest hand (what the play-mode tests assert, run here).</summary>
    public sealed class CalibrationStationTests
    {
        sealed class Store : ICalibrationSaver
        {
            public readonly List<double> Saved = new List<double>();
            public bool Fail;
            public string Save(in CalibrationResult result)
            {
                if (Fail) throw new System.IO.IOException("disk full");
                Saved.Add(result.StandardSpeed);
                return "user 'p01'";
            }
        }

        /// <summary>Rest 0.8 s, lift <paramref name="rise"/> m in <paramref name="duration"/> s, hold 0.6 s, lower in 0.6 s: heights per time.</summary>
        static Func<double, double> Lifts(double rest, params (double rise, double duration)[] lifts)
        {
            return t =>
            {
                foreach (var (rise, duration) in lifts)
                {
                    double length = 0.8 + duration + 0.6 + 0.6;
                    if (t < length)
                    {
                        if (t < 0.8) return rest;
                        if (t < 0.8 + duration) return rest + rise * QuestHand.MinimumJerk((t - 0.8) / duration);
                        if (t < 1.4 + duration) return rest + rise;
                        return rest + rise * (1 - QuestHand.MinimumJerk((t - 1.4 - duration) / 0.6));
                    }
                    t -= length;
                }
                return rest;
            };
        }

        static CalibrationStation Run(int wanted, Func<double, double> height, double seconds, Store store, int seed = 1, double frameRate = 90, int untilMeasurements = int.MaxValue)
        {
            var station = new CalibrationStation { LiftsWanted = wanted, Saver = store };
            station.Begin(true);
            var hand = new QuestHand { Seed = seed, FrameRate = frameRate, Path = t => new Vector3d(0, height(t), 0.4) };
            foreach (HandFrame f in hand.Render(seconds))
                if (station.Measurements.Count < untilMeasurements) station.Tick(f.Dt, f.Tracked, f.Position.Y, double.NaN);
            return station;
        }

        [Test]
        public void FiveGolfBallLiftsGiveTheUsersStandardSpeedAndAreStored([Values(72.0, 90.0, 120.0)] double frameRate)
        {
            var store = new Store();
            var lifts = new[] { (0.3, 0.50), (0.3, 0.55), (0.3, 0.48), (0.3, 0.52), (0.3, 0.50) };
            CalibrationStation c = Run(5, Lifts(0.8, lifts), 5 * 2.6 + 1, store, frameRate: frameRate);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Accepted), c.Message);
            // 90 % of a 0.3 m minimum-jerk rise between 5 % and 95 % takes ~0.62 of the duration: ~0.87 m/s at 0.5 s.
            Assert.That(c.Result.StandardSpeed, Is.InRange(0.6, 1.2));
            Assert.That(c.Result.LiftsOffered, Is.EqualTo(5));
            Assert.That(store.Saved, Is.EqualTo(new[] { c.Result.StandardSpeed }));
            Assert.That(c.Message, Does.Contain("Saved for user 'p01'"));
        }

        [Test]
        public void LiftsThatAreTooSmallDoNotCountAndTheReasonIsShown()
        {
            CalibrationStation c = Run(2, Lifts(0.8, (0.04, 0.5)), 2.6 + 6, new Store(), untilMeasurements: 1);
            Assert.That(c.Measurements.Count, Is.EqualTo(1));
            Assert.That(c.Measurements[0].IsAccepted, Is.False);
            Assert.That(c.Measurements[0].Reason, Does.Contain("too short"));
            Assert.That(c.Message, Does.Contain("did not count").And.Contain("too short"));
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rest), "and asks for another lift");
        }

        [Test]
        public void WildlyInconsistentLiftsAreRejectedAndNothingIsStored()
        {
            var store = new Store();
            CalibrationStation c = Run(3, Lifts(0.8, (0.3, 0.25), (0.3, 0.6), (0.3, 2.0)), 3 * 2.0 + 2.85 + 1, store);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rejected), c.Message);
            Assert.That(c.Message, Does.Contain("inconsistent"));
            Assert.That(store.Saved, Is.Empty);
        }

        [Test]
        public void AFailedSaveIsSaidAndTheResultStillStands()
        {
            var store = new Store { Fail = true };
            Exception failed = null;
            var c = new CalibrationStation { LiftsWanted = 1, Saver = store };
            c.SaveFailed += e => failed = e;
            c.Begin(true);
            var hand = new QuestHand { Path = t => new Vector3d(0, Lifts(0.8, (0.3, 0.5))(t), 0) };
            foreach (HandFrame f in hand.Render(3)) c.Tick(f.Dt, f.Tracked, f.Position.Y, double.NaN);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Accepted), c.Message);
            Assert.That(c.Message, Does.Contain("Not saved: disk full"));
            Assert.That(failed, Is.Not.Null);
        }

        [Test]
        public void LossesAndGarbageNeitherCrashNorCountAsLifts([Range(1, 50)] int seed)
        {
            var random = new Random(seed);
            var c = new CalibrationStation { LiftsWanted = 3 };
            c.Begin(true);
            var hand = new QuestHand { Seed = seed, Path = t => new Vector3d(0, 0.8, 0) }.Lose(random.NextDouble() * 3, random.NextDouble() * 2).Glitch(random.NextDouble() * 4);
            foreach (HandFrame f in hand.Render(6)) c.Tick(f.Dt, f.Tracked, f.Tracked ? f.Position.Y : double.NaN, double.NaN);
            c.Tick(double.NaN, true, 0.8, double.NaN);
            c.Tick(0.011, true, double.PositiveInfinity, double.NaN);
            foreach (LiftMeasurement m in c.Measurements) Assert.That(m.IsAccepted, Is.False, "a resting hand with one wrong pose is no lift");
            Assert.That(c.Phase, Is.Not.EqualTo(CalibrationPhase.Accepted));
        }

        [Test]
        public void WithoutAHandTheStationSaysSoAndWaits()
        {
            var c = new CalibrationStation();
            c.Begin(false);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Idle));
            Assert.That(c.Message, Does.Contain("No hand"));
            c.Tick(0.011, true, 0.8, double.NaN);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Idle));
        }
    }
}
