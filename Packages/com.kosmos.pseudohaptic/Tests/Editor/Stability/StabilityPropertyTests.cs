using System;
using System.Collections.Generic;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// Properties P1–P10 asserted over many seeded scenarios rather than single examples (issue 3). Each failure
    /// names the seed and the scenario so it can be replayed alone.
    /// </summary>
    public class StabilityPropertyTests
    {
        const int Seeds = 150;

        static IEnumerable<int> SeedRange(int count, int offset = 0) { for (int i = 0; i < count; i++) yield return 1000 + offset + i; }

        [Test]
        public void NothingNonFiniteNoJumpAndNoFloorCrossingOnAdversarialInput()
        {
            foreach (int seed in SeedRange(Seeds))
            {
                var s = ScenarioGenerator.Adversarial(seed);
                var solver = ScenarioGenerator.Solver(s);
                var y = TraceReplay.Run(solver, s.Frames);
                bool floor = solver.Profile.Has<FloorClamp>();
                for (int i = 0; i < y.Length; i++)
                {
                    if (double.IsNaN(y[i]) || double.IsInfinity(y[i])) Assert.Fail(s + ": non-finite at frame " + i);
                    if (floor && y[i] < 0) Assert.Fail(s + ": below the floor at frame " + i);
                }
                // No jump: no step beyond the hand's own in the surrounding 100 ms (times a light object's gain) plus 1 cm.
                double beyond = QuestLikeInput.StepBeyondHand(s.Frames, y, solver.Gain, double.NegativeInfinity, double.PositiveInfinity);
                Assert.That(beyond, Is.LessThanOrEqualTo(0.01), s + ": a step beyond the hand's own");
            }
        }

        [Test]
        public void TheSameMotionOnAnyFrameClockEndsWithinOneCentimetre()
        {
            foreach (int seed in SeedRange(40, 2000))
            {
                var s = ScenarioGenerator.Clean(seed);
                double? first = null;
                string firstClock = null;
                // The clocks. (A 30 Hz frame clock with wobble skips some 30 Hz poses; where the speed cap
                // binds, capping one two-pose step differs from capping two steps, and the ends may differ by
                // centimetres. SolverPropertyTests.P7 covers 30 Hz frames on a lift the cap does not touch.)
                foreach (var rate in new[] { 60.0, 72, 90, 120 })
                    foreach (var wobble in new[] { 0.0, 0.4 })
                    {
                        var headset = new HeadsetSimulator { FrameRate = rate, FrameTimeWobble = wobble, PoseRate = 30, JitterSd = 0.0015, Seed = seed };
                        var y = TraceReplay.Run(ScenarioGenerator.Solver(s), headset.Render(s.Path, extra: 0.5));
                        double end = y[y.Length - 1];
                        string clock = rate + " Hz" + (wobble > 0 ? " irregular" : "");
                        if (first == null) { first = end; firstClock = clock; continue; }
                        Assert.That(end, Is.EqualTo(first.Value).Within(0.01), s + ": " + clock + " vs " + firstClock);
                    }
            }
        }

        [Test]
        public void AHandAtRestWithJitterMovesTheObjectLessThanOneCentimetreInTenSeconds()
        {
            foreach (int seed in SeedRange(Seeds, 3000))
            {
                var rng = new Random(seed);
                var headset = ScenarioGenerator.RandomHeadset(rng, seed);
                headset.JitterSd = 0.0015;
                var path = HandPath.StartAt(0.2 + rng.NextDouble()).Hold(10);
                var frames = headset.Render(path);
                string profile = ScenarioGenerator.Profiles[seed % 3];
                double mass = ScenarioGenerator.LogUniform(rng, 0.001, 1e6), v = ScenarioGenerator.LogUniform(rng, 0.05, 5);
                var y = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile), v), frames);
                double creep = 0;
                foreach (var value in y) creep = Math.Max(creep, Math.Abs(value - y[0]));
                Assert.That(creep, Is.LessThan(0.01), "seed " + seed + ": " + profile + ", " + mass.ToString("G3") + " kg, v_std " + v.ToString("G3") + ", " + headset.FrameRate + " Hz");
            }
        }

        [Test]
        public void WithTheOffsetCorrectionTheOffsetStaysWithinTheStatedCeiling()
        {
            foreach (int seed in SeedRange(Seeds, 4000))
            {
                var s = ScenarioGenerator.Clean(seed);
                s.Profile = NamedProfiles.PaperName;
                var y = TraceReplay.Run(ScenarioGenerator.Solver(s), s.Frames);
                double max = 0;
                for (int i = 0; i < y.Length; i++) max = Math.Max(max, Math.Abs(s.Frames[i].HandY - y[i]));
                Assert.That(max, Is.LessThanOrEqualTo(SolverPropertyTests.StatedCeiling + 1e-12), s + ", " + s.MassKg.ToString("G3") + " kg, v_std " + s.StandardSpeed.ToString("G3"));
            }
        }

        [Test]
        public void AfterTheSameLiftHeavierIsNeverHigher()
        {
            double[] masses = { 0.001, 0.01, 0.045, 0.2, 1, 5, 50, 1e6 };
            foreach (int seed in SeedRange(60, 5000))
            {
                var rng = new Random(seed);
                double start = 0.3 + rng.NextDouble() * 0.6, rise = 0.05 + rng.NextDouble() * 0.6, seconds = rise / (0.1 + rng.NextDouble());
                var path = HandPath.StartAt(start).Hold(0.3).MoveTo(start + rise, seconds).Hold(0.5);
                var frames = ScenarioGenerator.RandomHeadset(rng, seed).Render(path);
                string profile = ScenarioGenerator.Profiles[seed % 3];
                double v = ScenarioGenerator.LogUniform(rng, 0.05, 5), previous = double.PositiveInfinity;
                foreach (var m in masses)
                {
                    var y = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(m), NamedProfiles.Get(profile), v), frames);
                    double end = y[y.Length - 1];
                    Assert.That(end, Is.LessThanOrEqualTo(previous + SolverPropertyTests.P2Tolerance(profile)), "seed " + seed + ": " + profile + ", " + m + " kg, v_std " + v.ToString("G3"));
                    previous = end;
                }
            }
        }

        [Test]
        public void TheGolfBallStaysWithTheHandOnRealisticInput()
        {
            foreach (int seed in SeedRange(60, 6000))
            {
                var s = ScenarioGenerator.Clean(seed);
                // Known limit (stability.md): 60 Hz poses without timestamps under irregular frames can put two
                // poses in one frame, which reads as one step at twice the speed and meets the speed cap.
                if (s.Description.Contains("60 Hz poses without timestamps")) continue;
                s.MassKg = PhysicalConstants.StandardMassKg;
                s.StandardSpeed = 1.2; // faster than any mean speed the generator draws
                var solver = ScenarioGenerator.Solver(s);
                var y = TraceReplay.Run(solver, s.Frames);
                double max = 0;
                for (int i = 0; i < y.Length; i++) max = Math.Max(max, Math.Abs(s.Frames[i].HandY - y[i]));
                Assert.That(max, Is.LessThanOrEqualTo(0.005), s.ToString()); // P1's bound, not a constant of the solver
            }
        }

        [Test]
        public void HoldingStillAtTheCorrectionsThresholdDoesNotCreep()
        {
            foreach (int seed in SeedRange(80, 6000))
            {
                var rng = new Random(seed);
                var headset = ScenarioGenerator.RandomHeadset(rng, seed);
                headset.JitterSd = 0.0015;
                double mass = ScenarioGenerator.LogUniform(rng, 2, 1e6), v = ScenarioGenerator.LogUniform(rng, 0.1, 2);
                var path = HandPath.StartAt(0.6).Hold(0.3).MoveTo(1.4, 1.2).Hold(10.5);
                var frames = headset.Render(path);
                var y = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Paper, v), frames);
                // From 1 s after the lift ends (the hand's last ~45 ms of motion reach the solver late).
                int start = Array.FindIndex(frames, f => f.Time >= 2.5);
                double creep = 0;
                for (int i = start; i < y.Length; i++) creep = Math.Max(creep, Math.Abs(y[i] - y[start]));
                // Inside the correction's band the share of the hand's motion is judged at each step's midpoint, so
                // jitter up and down cancels (a rule judged at one end drew the object up to 17 mm toward the hand).
                Assert.That(creep, Is.LessThan(0.01), "seed " + seed + ": " + mass.ToString("G3") + " kg, v_std " + v.ToString("G3") + ", " + headset.FrameRate + " Hz");
                double finalOffset = frames[frames.Length - 1].HandY - y[y.Length - 1];
                // Not drawn to the hand: a lift faster than the user's v_std stops the offset's growth earlier (faster moves
                // further, P11b), so the bound is well below the paper's 0.2 m but far from the hand.
                Assert.That(finalOffset, Is.GreaterThan(0.1), "seed " + seed + ": still held in the band, not drawn to the hand");
            }
        }

        /// <summary>A lift and a lowering as a Quest delivers them: low-confidence poses in fast motion, one-pose glitches
        /// (a joint jumping 2–4 cm for one pose) and short losses (30–150 ms) at the start, middle or end of each move.</summary>
        internal static (TraceFrame[] degraded, TraceFrame[] clean, double[] restFrom) QuestLike(int seed)
        {
            var rng = new Random(seed);
            double up = 0.3 + rng.NextDouble() * 0.9, down = 0.3 + rng.NextDouble() * 0.9, rise = 0.2 + rng.NextDouble() * 0.3;
            var path = HandPath.StartAt(0.8).Hold(0.5).MoveTo(0.8 + rise, up).Hold(1.0).MoveTo(0.9, down).Hold(1.0);
            var headset = ScenarioGenerator.RandomHeadset(rng, seed);
            headset.WritePoseTime = true;
            var clean = headset.Render(path);
            headset.LowConfidenceAboveSpeed = 0.6;
            headset.LowConfidenceChance = 0.3;
            headset.GlitchChance = 0.03;
            headset.GlitchSize = 0.02 + rng.NextDouble() * 0.02;
            foreach (var (start, length) in new[] { (0.5, up), (1.5 + up, down) })
            {
                double where = rng.Next(3) switch { 0 => 0.02, 1 => length / 2, _ => length - 0.05 };
                headset.Drop(start + headset.Latency + where, 0.03 + rng.NextDouble() * 0.12);
            }
            return (headset.Render(path), clean, new[] { 0.5 + up + headset.Latency + 0.5, 1.5 + up + down + headset.Latency + 0.5 });
        }

        [Test]
        public void OnQuestLikeInputTheGolfBallStaysRigidAndHeavyObjectsEndWhereTheyWould()
        {
            foreach (int seed in SeedRange(60, 7000))
            {
                var (frames, clean, restFrom) = QuestLike(seed);
                int lowConfidence = 0, lost = 0;
                foreach (var f in frames) { if (f.LowConfidence) lowConfidence++; if (!f.Tracked) lost++; }
                Assert.That(lowConfidence + lost, Is.GreaterThan(0), "seed " + seed + ": the headset degrades the input");

                // The golf ball is the hand on every frame it is tracked (a low-confidence pose is followed, not remembered).
                var y = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(PhysicalConstants.StandardMassKg), NamedProfiles.Paper, 0.5), frames);
                for (int i = 0; i < frames.Length; i++)
                {
                    var f = frames[i];
                    if (!f.IsUsable) continue;
                    double offset = Math.Abs(f.HandY - y[i]);
                    bool rested = (f.Time >= restFrom[0] && f.Time < restFrom[0] + 0.5) || f.Time >= restFrom[1];
                    Assert.That(offset, Is.LessThanOrEqualTo(rested ? 0.001 : 0.005), "seed " + seed + ": golf ball at frame " + i + " (" + f.Time.ToString("0.000") + " s)");
                }
                // Heavier objects: never a step beyond the hand's, never past the stated ceiling under the correction, and they
                // end where they end on the clean input (issue 22, rule 1: within 10 mm), with and without the correction.
                foreach (var m in new[] { 0.5, 2.0 })
                    foreach (var profile in new[] { NamedProfiles.Paper, NamedProfiles.PaperExperiment })
                    {
                        var solver = new WeightSolver(WeightModel.FromMass(m), profile, 0.5);
                        var heavy = TraceReplay.Run(solver, frames);
                        Assert.That(QuestLikeInput.StepBeyondHand(frames, heavy, solver.Gain, 0, double.PositiveInfinity), Is.LessThanOrEqualTo(0.01),
                            "seed " + seed + ": " + m + " kg, " + profile.Name + ", a step beyond the hand's");
                        if (profile.Has<OffsetCorrection>())
                            Assert.That(Run.MaxOffset(frames, heavy), Is.LessThanOrEqualTo(SolverPropertyTests.StatedCeiling + 1e-12), "seed " + seed + ": " + m + " kg, offset");
                        var reference = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(m), profile, 0.5), clean);
                        // At rest, the median over the last 0.3 s: the degraded input glitches 3 % of its poses, the last one too.
                        double end = frames[frames.Length - 1].Time;
                        Assert.That(QuestLikeInput.MedianOver(frames, i => heavy[i], end - 0.3, end),
                            Is.EqualTo(QuestLikeInput.MedianOver(clean, i => reference[i], end - 0.3, end)).Within(0.010),
                            "seed " + seed + ": " + m + " kg, " + profile.Name + " ends where it would on clean input");
                    }
            }
        }
    }
}