using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Faster moves further (§3.1, P11) as the lift's pace: the mean speed of its rise from the base, read on the steady
    /// hand, settled once the rise pauses, started over at the base. A faster lift leaves a heavy object higher; a heft after
    /// the lift, a loss during it or a glitch barely change the pace; the standard weight and lighter are untouched.
    /// </summary>
    public class FasterMovesFurtherTests
    {
        static readonly WeightProfile Profile = new WeightProfile("fmf", new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new FasterMovesFurther() });

        static WeightSolver Solver(double massKg, double standardSpeed = 0.5, WeightProfile profile = null)
            => new WeightSolver(WeightModel.FromMass(massKg), profile ?? Profile, standardSpeed);

        static TraceFrame[] Frames(HandPath path, int seed = 1) => Run.Headset(frameRate: 90, jitterSd: 0.001, seed: seed).Render(path);

        [Test]
        public void ALiftAtTheUsersStandardSpeedReadsAsTheStandard([Values(0.3, 0.5, 1.0)] double standardSpeed)
        {
            // The calibration measures v_std as the mean speed of a lift's 10–90 % span (StandardSpeedCalibration); a lift it
            // would measure at the user's v_std must read x = 1 here, where the gain is Eq. 4–6's own. Within 10 %.
            double rise = 0.3, seconds = 1.58 * rise / standardSpeed; // a minimum-jerk lift's 10–90 % mean speed is 1.58 R/T
            var path = HandPath.StartAt(0.8).Hold(0.5).MoveTo(0.8 + rise, seconds).Hold(0.5);
            var frames = Frames(path);
            var times = new double[frames.Length];
            var heights = new double[frames.Length];
            for (int i = 0; i < frames.Length; i++) { times[i] = frames[i].Time; heights[i] = path.HeightAt(frames[i].Time); }
            var measured = StandardSpeedCalibration.MeasureLift(times, heights);
            Assert.That(measured.IsAccepted, Is.True, measured.Reason);
            Assert.That(measured.Speed, Is.EqualTo(standardSpeed).Within(0.02 * standardSpeed), "the lift is a standard lift for this user");
            var solver = Solver(2, standardSpeed);
            Run.Replay(solver, frames);
            double x = FasterMovesFurther.StandardLiftRatio * solver.State.Pace / standardSpeed;
            Assert.That(x, Is.EqualTo(1).Within(0.1), "pace " + solver.State.Pace);
        }

        [Test]
        public void TheFasterLiftEndsHigherTheSlowerUserMovesItFurther([Values(0.5, 1, 2, 5)] double massKg)
        {
            double End(double seconds, double standardSpeed)
                => Run.Last(Run.Replay(Solver(massKg, standardSpeed), Frames(HandPath.StartAt(0.8).Hold(0.4).MoveTo(1.2, seconds).Hold(1))));
            double previous = double.NegativeInfinity;
            foreach (var seconds in new[] { 2.0, 1.0, 0.6, 0.3 })
            {
                double end = End(seconds, 0.5);
                Assert.That(end, Is.GreaterThan(previous + 0.001), $"{massKg} kg: a 0.4 m lift in {seconds} s ends above a slower one");
                previous = end;
            }
            Assert.That(End(1, 0.3), Is.GreaterThan(End(1, 1.0) + 0.001), $"{massKg} kg: moved further by a user with a lower v_std");
            Assert.That(End(0.3, 0.5), Is.LessThan(1.2 - 0.05), "still far below the hand: the weight stays");
        }

        [Test]
        public void AVerySlowLiftNeverEndsHigherThanAFasterOne([Values(1.0, 2.0)] double massKg, [Values(0.0, 0.0015)] double jitter)
        {
            // A rise slower than TopStep per PauseTime (under about 1.2 cm/s) read as a pause: it started over, had no pace,
            // got the standard's gain, and a 0.2 m lift in 15–30 s ended up to 11 mm above one in 10 s (P11 reversed). With
            // jitter, the mean end of ten seeds.
            double End(double seconds, int seed, bool minimumJerk)
            {
                var path = HandPath.StartAt(1.0).Hold(0.3);
                if (minimumJerk) path = path.MoveTo(1.2, seconds);
                else for (int i = 1; i <= 200; i++) path = path.MoveTo(1.0 + 0.001 * i, seconds / 200); // constant speed, mm by mm
                var frames = Run.Headset(jitterSd: jitter, seed: seed).Render(path.Hold(1.5));
                return Run.Last(Run.Replay(Solver(massKg, 0.5, NamedProfiles.PaperExperiment), frames));
            }
            int seeds = jitter > 0 ? 10 : 1;
            foreach (bool minimumJerk in new[] { false, true })
            {
                double previous = double.PositiveInfinity;
                foreach (double seconds in new[] { 2.0, 5.0, 10.0, 15.0, 20.0, 30.0 })
                {
                    double mean = 0;
                    for (int seed = 1; seed <= seeds; seed++) mean += End(seconds, seed, minimumJerk) / seeds;
                    Assert.That(mean, Is.LessThan(previous), $"{massKg} kg, jitter {jitter}, {(minimumJerk ? "minimum-jerk" : "constant-speed")} lift in {seconds} s: not above a faster one");
                    previous = mean;
                }
            }
        }

        [Test]
        public void TheStandardWeightAndLighterAreUntouched([Values(0.001, 0.02, 0.045)] double massKg)
        {
            var frames = Frames(HandPath.StartAt(0.8).Hold(0.4).MoveTo(1.2, 0.3).Hold(1));
            var with = Run.Replay(Solver(massKg), frames);
            var without = Run.Replay(Solver(massKg, profile: Profile.Without<FasterMovesFurther>()), frames);
            Assert.That(with, Is.EqualTo(without));
        }

        /// <summary>A scene's own lift effect, listed before faster-moves-further, that halves the frame's gain.</summary>
        sealed class HalvesTheGain : WeightEffect
        {
            public override string Name => "halves-the-gain";
            public override EffectStage Stage => EffectStage.Lift;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => frame.Gain *= 0.5;
        }

        [Test]
        public void AtTheStandardWeightAGainAnEarlierEffectGaveIsLeftAsItIs([Values(0.02, 0.045)] double massKg)
        {
            // "Applied only below 1": at the golf ball's gain of exactly 1 (and lighter) the effect leaves the frame's gain
            // alone, also when a scene's effect before it changed it, as it would for the standard weight's own gain.
            var frames = Frames(HandPath.StartAt(0.8).Hold(0.4).MoveTo(1.2, 0.3).Hold(1));
            var profile = new WeightProfile("halved", new WeightEffect[] { new WeightGain(), new HalvesTheGain(), new FasterMovesFurther() });
            var with = Run.Replay(Solver(massKg, profile: profile), frames);
            var without = Run.Replay(Solver(massKg, profile: profile.Without<FasterMovesFurther>()), frames);
            Assert.That(with, Is.EqualTo(without));
        }

        [Test]
        public void APacedLiftSettlesOnceItPausesAndAHeftLeavesItAsItWas([Values(0.3, 2.0)] double heftSeconds)
        {
            // A 0.3 m lift in 1 s, a 0.5 s rest, then a heft of 10 cm up and back in 0.3 s or 2 s: the pace does not change,
            // and the object is back exactly where it was (the map of the lift is the same).
            var path = HandPath.StartAt(0.8).Hold(0.4).MoveTo(1.1, 1).Hold(0.5);
            double rested = path.Duration;
            path.MoveTo(1.2, heftSeconds / 2).MoveTo(1.1, heftSeconds / 2).Hold(0.5);
            var solver = Solver(2);
            var frames = Run.Headset(frameRate: 90, seed: 2).Render(path);
            var y = new double[frames.Length];
            solver.BeginHold(frames[0].HandY, frames[0].HandY, frames[0].PoseTime);
            double paceAtRest = double.NaN, yAtRest = double.NaN;
            for (int i = 1; i < frames.Length; i++)
            {
                y[i] = solver.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
                if (double.IsNaN(paceAtRest) && frames[i].Time >= rested) { paceAtRest = solver.State.Pace; yAtRest = y[i]; }
            }
            Assert.That(solver.State.PaceSettled, Is.True);
            Assert.That(solver.State.Pace, Is.EqualTo(paceAtRest), "the heft did not change the pace");
            Assert.That(Run.Last(y), Is.EqualTo(yAtRest).Within(1e-9), "and left the object where it was");
        }

        [Test]
        public void BackAtTheBaseTheNextLiftHasItsOwnPace()
        {
            var path = HandPath.StartAt(0.8).Hold(0.4).MoveTo(1.1, 0.4).Hold(0.5).MoveTo(0.8, 1).Hold(0.5).MoveTo(1.1, 2).Hold(0.5);
            var profile = Profile.With(new LoweringGuard());
            var solver = Solver(2, 0.5, profile);
            Run.Replay(solver, Run.Headset(frameRate: 90, seed: 3).Render(path));
            double slowOnly = Solver(2, 0.5, profile).State.Pace;
            var second = Solver(2, 0.5, profile);
            Run.Replay(second, Run.Headset(frameRate: 90, seed: 3).Render(HandPath.StartAt(0.8).Hold(0.4).MoveTo(1.1, 2).Hold(0.5)));
            Assert.That(solver.State.Pace, Is.EqualTo(second.State.Pace).Within(0.05 * second.State.Pace), "the second lift's own (slow) pace");
            Assert.That(solver.State.Pace, Is.LessThan(0.3), "not the first, fast lift's");
            Assert.That(slowOnly, Is.EqualTo(0), "a solver that has not held reads no pace");
        }

        [Test]
        public void ALossThatHidesTheTopOfTheRiseGivesNearlyTheSamePace([Values(0.2, 0.5, 1.0)] double loss)
        {
            // The rise's time across a gap is taken at its pace so far: the pace comes out within 10 % of the clean one.
            var path = HandPath.StartAt(0.8).Hold(0.4).MoveTo(1.2, 0.8).Hold(1.5);
            var clean = Solver(2);
            Run.Replay(clean, Run.Headset(frameRate: 90, seed: 4).Render(path));
            var lost = Solver(2);
            Run.Replay(lost, Run.Headset(frameRate: 90, seed: 4).Drop(0.9, loss).Render(path));
            Assert.That(lost.State.Pace, Is.EqualTo(clean.State.Pace).Within(0.1 * clean.State.Pace), "a loss of " + loss + " s");
        }

        [Test]
        public void TheExponentFollowsThePaceWithinItsBoundsAndIsOneBeforeAnyRise()
        {
            var e = new FasterMovesFurther();
            double standardPace = 0.5 / FasterMovesFurther.StandardLiftRatio;
            Assert.That(e.ExponentAt(0, 0.5), Is.EqualTo(1), "no pace yet: Eq. 4–6's gain");
            Assert.That(e.ExponentAt(standardPace, 0.5), Is.EqualTo(1).Within(1e-12), "the user's standard pace");
            Assert.That(e.ExponentAt(4 * standardPace, 0.5), Is.EqualTo(Math.Pow(4, -e.Sensitivity)).Within(1e-12), "faster: r < 1");
            Assert.That(e.ExponentAt(standardPace / 4, 0.5), Is.EqualTo(Math.Pow(4, e.Sensitivity)).Within(1e-12), "slower: r > 1");
            Assert.That(e.ExponentAt(1e12, 0.5), Is.EqualTo(e.FastExponent), "bounded");
            Assert.That(e.ExponentAt(1e-12, 0.5), Is.EqualTo(e.SlowExponent), "bounded");
            Assert.That(e.GainAt(0.32, 4 * standardPace, 0.5), Is.GreaterThan(0.32).And.LessThan(1), "faster: closer to 1, never past it");
            Assert.That(e.GainAt(1.5, 4 * standardPace, 0.5), Is.EqualTo(1.5), "lighter objects untouched");
            Assert.That(() => new FasterMovesFurther(sensitivity: -1), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("sensitivity"));
            Assert.That(() => new FasterMovesFurther(pauseTime: 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("pauseTime"));
            Assert.That(() => new FasterMovesFurther(fastExponent: 2), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("fastExponent"));
            Assert.That(e.Name, Is.EqualTo("faster-moves-further"));
        }
    }
}
