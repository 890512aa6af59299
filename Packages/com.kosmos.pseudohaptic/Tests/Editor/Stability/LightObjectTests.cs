using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// Issue 32, "Objects lighter than the standard amplify what is not motion": the cases the issue lists, each as found.
    /// A light object's gain is above 1, so a hand's step across a gap, followed as motion, moved it up to 3 × as far in one
    /// frame. The rule (<see cref="GapRule"/>): across a gap the object steps no more than the hand + 1 cm, and what a
    /// clean run would have done beyond that glides; a pose outside any plausible workspace is not tracked.
    /// </summary>
    public class LightObjectTests
    {
        static TraceFrame[] Render(HandPath path, double fps = 90, double jitter = 0, int seed = 1)
            => new HeadsetSimulator { FrameRate = fps, PoseRate = 30, Latency = 0.045, JitterSd = jitter, Seed = seed }.Render(path);

        static void AssertRule(TraceFrame[] frames, double[] y, WeightSolver solver, string what)
        {
            double excess = GapRule.WorstExcess(frames, y, solver.Gain, out int i);
            Assert.That(excess, Is.LessThanOrEqualTo(0), $"{what}: a step beyond the rule at frame {i} (t = {(i >= 0 ? frames[i].Time : 0):F3} s): " +
                $"object {y[Math.Max(i - 1, 0)]:F4} -> {y[Math.Max(i, 0)]:F4} m");
        }

        [Test]
        public void ATenSecondHitchWhileTheHandMoves40cm([Values("paper-experiment", "gain", "paper", "xyz")] string profile)
        {
            var path = HandPath.StartAt(0.8).Hold(1).MoveTo(1.2, 10).Hold(5);
            var clean = Render(path);
            var hitched = GapRule.WithHitch(clean, 1.0, 10.0);
            var solver = Run.Solver(0.001, NamedProfiles.Get(profile));
            var y = Run.Replay(solver, hitched);
            AssertRule(hitched, y, solver, "1 g through a 10 s hitch");
            double reference = Run.Last(Run.Replay(Run.Solver(0.001, NamedProfiles.Get(profile)), clean));
            Assert.That(Run.Last(y), Is.EqualTo(reference).Within(0.002), "glided to where the clean run ends");
        }

        [Test]
        public void TheEndOfASixtyFrameNaNGap([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            var path = HandPath.StartAt(0.8).Hold(0.5).MoveTo(1.2, 1.0).Hold(3);
            var clean = Render(path);
            var gap = (TraceFrame[])clean.Clone();
            int from = QuestLikeInput.FrameAt(gap, 0.6);
            for (int i = from; i < from + 60; i++) gap[i] = new TraceFrame(gap[i].Time, double.NaN, true, gap[i].PoseTime);
            var solver = Run.Solver(0.001, NamedProfiles.Get(profile));
            var y = Run.Replay(solver, gap);
            AssertRule(gap, y, solver, "1 g after 60 NaN frames");
            double reference = Run.Last(Run.Replay(Run.Solver(0.001, NamedProfiles.Get(profile)), clean));
            Assert.That(Run.Last(y), Is.EqualTo(reference).Within(0.002), "glided to where the clean run ends");
        }

        [Test]
        public void ALossAfterWhichTheHandIs30cmLower([Values(0.001, 0.01, 0.02, 0.03)] double massKg, [Values("gain", "paper", "paper-experiment")] string profile)
        {
            var path = HandPath.StartAt(1.1).Hold(0.5).MoveTo(0.8, 0.5).Hold(3);
            var clean = Render(path);
            var lost = new HeadsetSimulator { FrameRate = 90, PoseRate = 30, Latency = 0.045 }.Drop(0.45, 0.6).Render(path);
            var solver = Run.Solver(massKg, NamedProfiles.Get(profile));
            var y = Run.Replay(solver, lost);
            AssertRule(lost, y, solver, $"{massKg * 1000} g after a 0.6 s loss");
            double reference = Run.Last(Run.Replay(Run.Solver(massKg, NamedProfiles.Get(profile)), clean));
            Assert.That(Run.Last(y), Is.EqualTo(reference).Within(0.002), "glided to where the clean run ends");
        }

        [Test]
        public void ATenSecondHitchWhileTheHandMoves156cm()
        {
            var path = HandPath.StartAt(0.2).Hold(1).MoveTo(1.76, 10).Hold(12);
            var clean = Render(path);
            var hitched = GapRule.WithHitch(clean, 1.0, 10.0);
            var solver = Run.Solver(0.001, NamedProfiles.Gain);
            var y = Run.Replay(solver, hitched);
            AssertRule(hitched, y, solver, "1 g through a 10 s hitch");
            double reference = Run.Last(Run.Replay(Run.Solver(0.001, NamedProfiles.Gain), clean));
            Assert.That(Run.Last(y), Is.EqualTo(reference).Within(0.002), "glided to where the clean run ends");
        }

        [Test]
        public void TwoHandsReacquiredAfter08s([Values("paper-experiment", "xyz")] string profile)
        {
            HandPath3D left = (double t, out double x, out double y, out double z) => { x = -0.2; y = Headset3D.MinJerk(t, 0.5, 1.0, 0.8, 1.1); z = 0.3; };
            HandPath3D right = (double t, out double x, out double y, out double z) => { x = 0.2; y = Headset3D.MinJerk(t, 0.5, 1.0, 0.8, 1.1); z = 0.3; };
            var frames = new Headset3D().Drop(1, 0.5, 0.8).Drop(2, 0.5, 0.8).Render(left, right, 4);
            var solver = new WeightSolver3D(WeightModel.FromMass(0.001), NamedProfiles.Get(profile));
            var r = Run3D.Of(solver, frames);
            var usable = new bool[frames.Count];
            var hand = new double[frames.Count];
            for (int i = 0; i < frames.Count; i++)
            {
                usable[i] = frames.A[i].IsUsable || frames.B[i].IsUsable;
                hand[i] = usable[i] ? 0.5 * (frames.A[i].Y + frames.B[i].Y) : double.NaN;
            }
            double excess = GapRule.WorstExcess(frames.T, usable, hand, r.Y, solver.Vertical.Gain, out int at);
            Assert.That(excess, Is.LessThanOrEqualTo(0), $"1 g, two hands back after 0.8 s: frame {at}, object {r.Y[Math.Max(at - 1, 0)]:F4} -> {r.Y[Math.Max(at, 0)]:F4} m");
        }

        /// <summary>The workspace is a setting (<see cref="SolverLimits.WorkspaceRadius"/>): after a 2 s loss the hand is seen
        /// 3 m above where the hold began; a hold whose workspace is 2 m treats it as not tracked (the object stays), one whose
        /// workspace is 5 m follows it, in y and in 3D.</summary>
        [Test]
        public void TheWorkspaceRadiusIsASetting([Values(2.0, 5.0)] double radius, [Values("paper", "xyz")] string name)
        {
            var profile = NamedProfiles.Get(name).WithLimits(new SolverLimits(workspaceRadius: radius));
            var y = new WeightSolver(WeightModel.FromMass(1), profile);
            var s3 = new WeightSolver3D(WeightModel.FromMass(1), profile);
            y.BeginHold(1.0, 1.0, 0);
            s3.BeginHold(new HandPose(0, 1.0, 0, true, true, 0), 0, 1.0, 0);
            double t = 0;
            for (int i = 0; i < 180; i++) { t += 1 / 90.0; y.Step(HandSample.Lost, 1 / 90.0); s3.Step(HandPose.Lost, 1 / 90.0); }
            for (int i = 0; i < 90; i++)
            {
                t += 1 / 90.0;
                double poseT = Math.Floor(t * 30) / 30;
                y.Step(new HandSample(4.0, true, true, poseT), 1 / 90.0);
                s3.Step(new HandPose(0, 4.0, 0, true, true, poseT), 1 / 90.0);
            }
            if (radius < 3)
            {
                Assert.That(y.ObjectY, Is.EqualTo(1.0), "y: outside the workspace, not tracked");
                Assert.That(s3.ObjectY, Is.EqualTo(1.0), "3D: outside the workspace, not tracked");
            }
            else
            {
                Assert.That(y.ObjectY, Is.GreaterThan(2.0), "y: within the workspace, followed");
                Assert.That(s3.ObjectY, Is.GreaterThan(2.0), "3D: within the workspace, followed");
            }
        }

        /// <summary>Found by fuzzing: the clock jumps to t = 1e308 with a pose reported as tracked at 99,999.99 m. A finite
        /// pose far outside any room is not motion: nothing follows it, whatever the mass or profile.</summary>
        [Test]
        public void AClockJumpToOneE308WithATrackedPoseAt99999m([Values(0.001, 0.02, 1, 1000)] double massKg,
            [Values("paper", "paper-experiment", "gain", "xyz")] string profile, [Values(1, 30)] int farFrames)
        {
            var frames = new List<TraceFrame>(Render(HandPath.StartAt(0.8).Hold(0.5).MoveTo(1.0, 0.5).Hold(0.5)));
            double resume = frames[frames.Count - 1].Time;
            for (int i = 0; i < farFrames; i++) frames.Add(new TraceFrame(1e308, 99_999.99, true, 1e308));
            foreach (var f in Render(HandPath.StartAt(1.0).Hold(2))) frames.Add(new TraceFrame(resume + 0.011 + f.Time, f.HandY, true, resume + f.PoseTime));
            var y = Run.Replay(Run.Solver(massKg, NamedProfiles.Get(profile)), frames.ToArray());
            for (int i = 0; i < y.Length; i++)
                Assert.That(y[i], Is.InRange(0.0, 2.0), $"{massKg} kg, frame {i}: the object stays in the room");
            Assert.That(Run.Last(y), Is.EqualTo(Run.Last(Run.Replay(Run.Solver(massKg, NamedProfiles.Get(profile)),
                Render(HandPath.StartAt(0.8).Hold(0.5).MoveTo(1.0, 0.5).Hold(2.5))))).Within(0.005), "and ends where the run without the jump ends");
        }
    }
}
