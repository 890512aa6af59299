using System;
using System.Collections.Generic;
using System.Globalization;
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
            Assert.That(c.Message, Does.Contain("try again"), "a lift too small to lower from asks for another at once");
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
            // Scripted frames (issue 35): at 32 frames a second every time is exact in binary, so a boundary (RestTime,
        // SettleTime, MaxLiftTime, StillBand) falls exactly on a frame. RestTime is the default 0.5 s = 16 frames; the
        // first frame sets the still reference, so a lift starts on the 17th still frame.
        const double Dt = 1.0 / 32;

        static CalibrationStation Scripted(int wanted) => new CalibrationStation { LiftsWanted = wanted, SettleTime = 10 * Dt };

        static void Frames(CalibrationStation c, params double[] heights)
        {
            foreach (double y in heights) c.Tick(Dt, true, y, double.NaN);
        }

        static void Still(CalibrationStation c, double y, int frames)
        {
            for (int i = 0; i < frames; i++) c.Tick(Dt, true, y, double.NaN);
        }

        /// <summary>The heights after <paramref name="from"/> up to <paramref name="to"/> in <paramref name="n"/> equal steps.</summary>
        static double[] Ramp(double from, double to, int n)
        {
            var r = new double[n];
            for (int i = 1; i <= n; i++) r[i - 1] = i == n ? to : from + (to - from) * i / n;
            return r;
        }

        /// <summary>Rests at 0.8 m until the lift starts, rises 0.3 m in 10 frames and holds the top SettleTime.</summary>
        static void GoodLift(CalibrationStation c)
        {
            Still(c, 0.8, 17);
            Frames(c, Ramp(0.8, 1.1, 10));
            Still(c, 1.1, 10);
        }

        [Test]
        public void ANewStationSaysNothingAndBeginAsksForTheBallAtRest()
        {
            var c = new CalibrationStation();
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Idle));
            Assert.That(c.Message, Is.Empty, "nothing to show before Begin");
            c.Begin(true);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rest));
            Assert.That(c.Message, Does.Contain("Hold the golf ball still"));
        }

        [Test]
        public void ALiftStartsOnceTheBallRestedRestTimeWithinTheBandAndSaysWhichLiftItIs()
        {
            var c = Scripted(3);
            c.StillBand = Dt / 2; // 1/64 m, exact
            c.Begin(true);
            // A hand jittering by exactly the band stays within it: still.
            for (int i = 0; i < 16; i++)
            {
                c.Tick(Dt, true, i % 2 == 0 ? 1.0 : 1.0 + c.StillBand, double.NaN);
                Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rest), "frame " + (i + 1));
            }
            c.Tick(Dt, true, 1.0, double.NaN);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lift), "still for exactly RestTime since the first frame");
            Assert.That(c.Message, Does.StartWith("Lift 1 of 3: ").And.Contain("lift the ball up"));
        }

        [Test]
        public void TheLiftIsMeasuredFromEveryNewPoseSinceItsStartEvenOneAtTheSameHeight()
        {
            var c = Scripted(1);
            c.Begin(true);
            var times = new List<double>();
            var heights = new List<double>();
            double clock = 0;
            int pose = 0;
            void Frame(double y)
            {
                CalibrationPhase before = c.Phase;
                clock += Dt;
                c.Tick(Dt, true, y, pose++); // every frame a new pose, its time known
                if (before == CalibrationPhase.Lift || c.Phase == CalibrationPhase.Lift) { times.Add(clock); heights.Add(y); }
            }
            for (int i = 0; i < 17; i++) Frame(1.0);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lift));
            foreach (double y in Ramp(1.0, 1.02, 2)) Frame(y);
            for (int i = 0; i < 6; i++) Frame(1.02); // a pause just below 10 % of the rise: new poses at one height
            foreach (double y in Ramp(1.02, 1.3, 10)) Frame(y);
            for (int i = 0; i < 40 && c.Phase == CalibrationPhase.Lift; i++) Frame(1.3);
            Assert.That(c.Measurements.Count, Is.EqualTo(1), c.Message);
            LiftMeasurement expected = StandardSpeedCalibration.MeasureLift(times.ToArray(), heights.ToArray());
            Assert.That(expected.IsAccepted, Is.True, expected.Reason);
            Assert.That(expected.Rise, Is.EqualTo(0.3).Within(1e-9), "from the resting height the lift started at");
            Assert.That(c.Measurements[0].Rise, Is.EqualTo(expected.Rise));
            Assert.That(c.Measurements[0].Speed, Is.EqualTo(expected.Speed));
        }

        [Test]
        public void RepeatedPosesOfUnknownTimeAreRecordedOnce()
        {
            // The same poses at 32 Hz, drawn once per frame at 32 fps or four times each at 128 fps (pose time unknown).
            var poses = new List<double>();
            for (int i = 0; i < 17; i++) poses.Add(1.0);
            for (int i = 1; i <= 10; i++) poses.Add(1.0 + 0.3 * QuestHand.MinimumJerk(i / 10.0)); // 10 % and 90 % between poses
            for (int i = 0; i < 15; i++) poses.Add(1.3);
            LiftMeasurement Measure(int repeats)
            {
                var c = Scripted(1);
                c.Begin(true);
                foreach (double y in poses)
                    for (int r = 0; r < repeats; r++) c.Tick(Dt / repeats, true, y, double.NaN);
                Assert.That(c.Measurements.Count, Is.EqualTo(1), c.Message);
                return c.Measurements[0];
            }
            LiftMeasurement once = Measure(1), four = Measure(4);
            Assert.That(once.IsAccepted, Is.True, once.Reason);
            Assert.That(four.Rise, Is.EqualTo(once.Rise).Within(1e-12));
            Assert.That(four.Speed, Is.EqualTo(once.Speed).Within(1e-9));
        }

        [Test]
        public void ALiftOfExactlyTheSmallestRiseEndsOnceHeldSettleTimeAtItsTopAndCounts()
        {
            // At 5⅓ frames a second the ball goes from the table (0 m) to exactly MinRise (0.1 m) in one frame, so no
            // height in between enters the core's smoothing and the rise it measures is exactly 0.1 m too.
            const double dt = 3.0 / 16;
            var c = new CalibrationStation { LiftsWanted = 1, SettleTime = 2 * dt };
            c.Begin(true);
            int pose = 0; // pose times known: a new pose at the same height counts
            for (int i = 0; i < 4; i++) c.Tick(dt, true, 0.0, pose++);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lift));
            c.Tick(dt, true, 0.1, pose++);
            c.Tick(dt, true, 0.1, pose++);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lift), "held at the top one frame less than SettleTime");
            c.Tick(dt, true, 0.1, pose++);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Accepted), c.Message);
        }

        [Test]
        public void ABallHeldWithinTheBandBelowItsTopIsHeldAtTheTop()
        {
            var c = Scripted(1);
            c.StillBand = Dt / 2; // 1/64 m, exact
            c.Begin(true);
            Still(c, 0.0, 17);
            Frames(c, 0.05, 0.1, 0.15, 0.2, 0.25);
            Still(c, 0.25 - c.StillBand, 10); // sagged by exactly the band, still for SettleTime
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Accepted), c.Message);
        }

        [Test]
        public void AfterALiftTheStationWaitsForTheBallToBeLoweredThenAsksForTheNext()
        {
            var c = Scripted(3);
            c.Begin(true);
            GoodLift(c);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lower), c.Message);
            LiftMeasurement m = c.Measurements[0];
            Assert.That(m.IsAccepted, Is.True, m.Reason);
            Assert.That(c.Message, Does.StartWith("Lift 1: " + m.Speed.ToString("0.00", CultureInfo.InvariantCulture) + " m/s.").And.Contain("Lower the ball"));
            Still(c, 1.1, 32);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lower), "a ball held at the top is not lowered");
            Frames(c, Ramp(1.1, 0.8, 10));
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rest));
            Assert.That(c.Message, Does.StartWith("Hold the ball still for lift 2 of 3").And.EndWith("."));
        }

        /// <summary>
        /// A lift that rose half the smallest lift (5 cm) or more waits for the ball lowered by as much from its top before the
        /// next rest; a smaller one asks for the rest at once. Both at their exact edge: from 5 cm to 10 cm (0.1 − 0.05 is
        /// 0.05 exactly in doubles), held there until MaxLiftTime ends the lift (too small to count), then lowered to 5 cm.
        /// </summary>
        [Test]
        public void ALiftOfHalfTheSmallestRiseWaitsForTheBallLoweredByHalfTheSmallestRise()
        {
            double half = 0.5 * StandardSpeedCalibration.MinRise;
            Assert.That(2 * half - half, Is.EqualTo(half), "the heights below are exact");
            var c = Scripted(2);
            c.MaxLiftTime = 1;
            c.Begin(true);
            Still(c, half, 17);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lift));
            Frames(c, 2 * half);
            Still(c, 2 * half, 40);
            Assert.That(c.Measurements.Count, Is.EqualTo(1), "ended by MaxLiftTime");
            Assert.That(c.Measurements[0].IsAccepted, Is.False, "smaller than the smallest lift");
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lower), "risen half the smallest lift: lower the ball first");
            Assert.That(c.Message, Does.EndWith(" Lower the ball to the table."));
            Frames(c, 2 * half - half / 2);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lower), "lowered a quarter of the smallest lift");
            Frames(c, half);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rest), "lowered half the smallest lift from the top");

            // A hair less than half the smallest lift: the rest is asked for at once.
            var d = Scripted(2);
            d.MaxLiftTime = 1;
            d.Begin(true);
            Still(d, half, 17);
            Still(d, 2 * half - 1e-9, 40);
            Assert.That(d.Measurements.Count, Is.EqualTo(1));
            Assert.That(d.Phase, Is.EqualTo(CalibrationPhase.Rest));
            Assert.That(d.Message, Does.EndWith(" Hold the ball still to try again."));
        }

        /// <summary>Faster than the 250 new poses a second the buffer is sized for (no headset tracks that fast), a lift ends
        /// when its buffer is full, measured from what it holds, rather than running on with nothing more recorded.</summary>
        [Test]
        public void AboveTwoHundredFiftyPosesASecondALiftEndsWhenItsBufferIsFull()
        {
            var (c, rising) = SlowLift(1.0 / 1024, 0.0001);
            Assert.That(c.Measurements.Count, Is.EqualTo(1));
            Assert.That(1 + rising, Is.EqualTo((int)(c.MaxLiftTime * 250) + 2), "the buffer's samples (the lift's first and each rising pose)");
        }

        [Test]
        public void ALiftThatRanOutOfTimeBackNearItsStartDoesNotCountAndSaysWhy()
        {
            var c = Scripted(2);
            c.MaxLiftTime = 1;
            c.Begin(true);
            Still(c, 0.8, 17);
            Frames(c, Ramp(0.8, 1.1, 10));
            Frames(c, Ramp(1.1, 0.8, 10)); // straight back down, never held at the top
            Still(c, 0.8, 12);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lift), "MaxLiftTime (32 frames) reached, not yet passed");
            Still(c, 0.8, 1);
            Assert.That(c.Measurements.Count, Is.EqualTo(1), "ended once longer than MaxLiftTime");
            LiftMeasurement m = c.Measurements[0];
            Assert.That(m.IsAccepted, Is.False);
            Assert.That(m.Reason, Does.Contain("not held up at the top"));
            Assert.That(c.Message, Does.StartWith("That lift did not count: " + m.Reason + ". "));
        }

        [Test]
        public void TwiceTheWantedLiftsAreTriedThenItEndsRejectedAndBeginStartsAfresh()
        {
            var c = Scripted(1);
            int completed = 0;
            CalibrationResult got = default;
            c.Completed += r => { completed++; got = r; };
            c.Begin(true);
            for (int i = 0; i < 2; i++)
            {
                Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rest), "try " + (i + 1));
                Still(c, 0.8, 17);
                Frames(c, 1.1); // a jump, far too quick to be a lift
                Still(c, 1.1, 10);
                Assert.That(c.Measurements.Count, Is.EqualTo(i + 1));
                Assert.That(c.Measurements[i].IsAccepted, Is.False);
                if (i == 0)
                {
                    Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lower), c.Message);
                    Frames(c, 0.8);
                }
            }
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rejected), c.Message);
            Assert.That(c.Message, Does.StartWith("Calibration rejected: ").And.Contain(c.Result.Reason).And.EndWith(". Begin again."));
            Assert.That(completed, Is.EqualTo(1));
            Assert.That(got.IsAccepted, Is.False);
            c.Begin(true);
            Assert.That(c.Measurements, Is.Empty, "a new calibration forgets the last one's lifts");
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Rest));
            Assert.That(c.Message, Does.Contain("Hold the golf ball still"));
        }

        [Test]
        public void AnAcceptedCalibrationSaysTheSpeedAndWhetherItWasSaved([Values(false, true)] bool withStore)
        {
            var store = withStore ? new Store() : null;
            var c = Scripted(1);
            c.Saver = store;
            int completed = 0;
            c.Completed += r => completed++;
            c.Begin(true);
            GoodLift(c);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Accepted), c.Message);
            Assert.That(completed, Is.EqualTo(1));
            string said = "Your standard speed: " + c.Result + ".";
            Assert.That(c.Message, Is.EqualTo(withStore ? said + " Saved for user 'p01'." : said));
        }

        [Test]
        public void FramesWithoutTimeOrWithoutAUsableHandChangeNothing()
        {
            // The same two lifts, clean and with each frame split into quarters and garbage frames around it.
            var heights = new List<double>();
            for (int i = 0; i < 17; i++) heights.Add(0.8);
            heights.AddRange(Ramp(0.8, 1.1, 10));
            for (int i = 0; i < 10; i++) heights.Add(1.1);
            heights.AddRange(Ramp(1.1, 0.8, 10));
            for (int i = 0; i < 17; i++) heights.Add(0.8);
            heights.AddRange(Ramp(0.8, 1.1, 10));
            for (int i = 0; i < 10; i++) heights.Add(1.1);
            var clean = Scripted(2);
            clean.Begin(true);
            foreach (double y in heights) clean.Tick(Dt, true, y, double.NaN);
            Assert.That(clean.Phase, Is.EqualTo(CalibrationPhase.Accepted), clean.Message);

            var noisy = Scripted(2);
            noisy.Begin(true);
            foreach (double y in heights)
            {
                foreach (double dt in new[] { 0, double.NaN, -Dt, double.PositiveInfinity, double.NegativeInfinity })
                    noisy.Tick(dt, true, 5.0, double.NaN); // no time passed (or nonsense): nothing to record
                noisy.Tick(Dt / 4, false, 0.0, double.NaN); // lost hand, its pose at the origin
                noisy.Tick(Dt / 4, true, double.NaN, double.NaN);
                noisy.Tick(Dt / 4, true, double.PositiveInfinity, double.NaN);
                noisy.Tick(Dt / 4, true, y, double.NaN);
            }
            Assert.That(noisy.Phase, Is.EqualTo(clean.Phase), noisy.Message);
            Assert.That(noisy.Message, Is.EqualTo(clean.Message));
            Assert.That(noisy.Measurements.Count, Is.EqualTo(clean.Measurements.Count));
            for (int i = 0; i < clean.Measurements.Count; i++)
                Assert.That(noisy.Measurements[i].Speed, Is.EqualTo(clean.Measurements[i].Speed), "lift " + (i + 1));
        }

        [Test]
        public void UpTo250PosesASecondALiftIsEndedByMaxLiftTimeNotByAFullBuffer()
        {
            // The buffer is sized for 250 samples a second ("above any tracking or frame rate").
            const double dt = 1.0 / 250;
            var (c, rising) = SlowLift(dt, 0.0005);
            Assert.That(rising * dt, Is.GreaterThanOrEqualTo(c.MaxLiftTime));
            Assert.That(c.Measurements.Count, Is.EqualTo(1));
        }

        /// <summary>A one-lift station given a new pose every <paramref name="dt"/> s: at rest at 0.8 m until its lift starts,
        /// then rising <paramref name="step"/> m a pose, never settling, until the lift ends (at most 8000 poses). Returns the
        /// station and the rising poses the lift took.</summary>
        static (CalibrationStation station, int rising) SlowLift(double dt, double step)
        {
            var c = new CalibrationStation { LiftsWanted = 1 };
            c.Begin(true);
            double y = 0.8;
            for (int i = 0; i < 8000 && c.Phase == CalibrationPhase.Rest; i++) c.Tick(dt, true, y, double.NaN);
            Assert.That(c.Phase, Is.EqualTo(CalibrationPhase.Lift));
            int rising = 0;
            for (; rising < 8000 && c.Phase == CalibrationPhase.Lift; rising++)
            {
                y += step;
                c.Tick(dt, true, y, double.NaN);
            }
            return (c, rising);
        }
    }
}
