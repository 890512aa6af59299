using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;
using Kosmos.PseudoHaptic.Tests.Stability;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// Issue 32's "Done when", first bullet: the light-object, implausible-pose and repeated-pose cases as properties over
    /// hundreds of seeds, every named profile, masses from 1 g to 1 t, on Quest-like input (<see cref="QuestLikeInput"/>:
    /// 30 Hz poses 45 ms late over 72/90/120 Hz frames, 1–2 mm jitter, low confidence at speed, one-pose glitches).
    /// Every bound is the issue's, not the code's.
    /// </summary>
    public class LightObjectPropertyTests
    {
        static readonly IReadOnlyList<string> Profiles = NamedProfiles.PipelineNames; // paper-literal is the printed method, run by PaperLiteralSolver, not this pipeline

        /// <summary>A third of the seeds lighter than the standard (1–45 g), the rest anywhere from 1 g to 1 t.</summary>
        static double Mass(Random rng, int seed)
            => seed % 3 == 0 ? ScenarioGenerator.LogUniform(rng, 0.001, PhysicalConstants.StandardMassKg) : ScenarioGenerator.LogUniform(rng, 0.001, 1000);

        enum Gap { Loss, NaNBurst, Hitch }

        /// <summary>
        /// A gap is never amplified. Random lifts and lowerings on Quest-like input (from 0.5 m, never below where the hold
        /// began), with one gap while the hand moves on: a loss (0.1–2 s), a burst of NaN poses reported as tracked (10–120
        /// frames) or a hitch (one frame of 0.15–10 s). On every frame the object keeps <see cref="GapRule"/> (across the gap,
        /// at most the hand's own step + 1 cm; elsewhere max(G, 1) × the hand's largest ordinary step within 100 ms + 1 cm),
        /// and after 10 s at rest it is where the same run without the gap leaves it: within 1 mm for the standard weight,
        /// 10 mm otherwise (issue 22's rule 1). That last is asserted for every gap for the standard weight and lighter, whose
        /// weight remembers only the base, and for gaps of up to 1 s (rule 1's) for heavier objects, whose lift's pace a gap
        /// that hides a whole rise cannot measure. (Paths stay above where the hold began: a gap that hides the hand's lowest
        /// point hides where the lowering guard would have put the base, for any mass.)
        /// </summary>
        [Test]
        public void AGapIsNeverAmplifiedAndWhatACleanRunWouldHaveDoneGlides([Range(1, 300)] int seed)
        {
            var rng = new Random(seed);
            string profile = Profiles[seed % Profiles.Count];
            double mass = Mass(rng, seed), standardSpeed = QuestLikeInput.Uniform(rng, 0.3, 1.2);
            var path = HandPath.StartAt(0.5).Hold(QuestLikeInput.Uniform(rng, 0.2, 0.7));
            double hand = 0.5, seconds = 3 + 4 * rng.NextDouble();
            while (path.Duration < seconds)
            {
                double target = QuestLikeInput.Uniform(rng, 0.5, 1.7);
                path.MoveTo(target, Math.Max(0.15, Math.Abs(target - hand) / QuestLikeInput.Uniform(rng, 0.1, 1.2)));
                hand = target;
                if (rng.Next(2) == 0) path.Hold(QuestLikeInput.Uniform(rng, 0.1, 1.0));
            }
            double moving = path.Duration;
            path.Hold(10);
            var clean = QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(path);
            var kind = (Gap)(seed / 4 % 3);
            double at = QuestLikeInput.Uniform(rng, 0.5, moving - 0.2), length;
            TraceFrame[] degraded;
            switch (kind)
            {
                case Gap.Loss:
                    length = QuestLikeInput.Uniform(rng, 0.1, 2.0);
                    var h = QuestLikeInput.Headset(new Random(seed * 7919), seed);
                    h.Drop(at, length);
                    degraded = h.Render(path);
                    break;
                case Gap.NaNBurst:
                    degraded = (TraceFrame[])clean.Clone();
                    int from = QuestLikeInput.FrameAt(degraded, at), n = 10 + rng.Next(111);
                    for (int i = from; i < Math.Min(degraded.Length - 1, from + n); i++)
                        degraded[i] = new TraceFrame(degraded[i].Time, double.NaN, true, degraded[i].PoseTime);
                    length = n;
                    break;
                default:
                    length = ScenarioGenerator.LogUniform(rng, 0.15, 10);
                    degraded = GapRule.WithHitch(clean, at, length);
                    break;
            }
            string what = $"seed {seed}: {profile}, {mass * 1000:G4} g, v_std {standardSpeed:F2}, {kind} at {at:F2} s ({length:G3})";
            var solver = new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile), standardSpeed);
            var y = Run.Replay(solver, degraded);
            Assert.That(Run.AllFinite(y), Is.True, what + ": finite");
            double excess = GapRule.WorstExcess(degraded, y, solver.Gain, out int worst);
            Assert.That(excess, Is.LessThanOrEqualTo(0), $"{what}: a step beyond the rule at {(worst >= 0 ? degraded[worst].Time : 0):F3} s");
            double hidden = kind == Gap.NaNBurst ? length / 72 : length; // s (at most: the slowest frame clock)
            if (mass > PhysicalConstants.StandardMassKg && hidden > 1) return;
            double reference = Run.Last(Run.Replay(new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile), standardSpeed), clean));
            double tolerance = mass == PhysicalConstants.StandardMassKg ? 0.001 : 0.010;
            Assert.That(Run.Last(y), Is.EqualTo(reference).Within(tolerance), what + ": where the clean run ends, 10 s after the motion");
        }

        /// <summary>
        /// A pose outside the workspace, or one no arm could have reached, is treated as not tracked: the same Quest-like run
        /// with some poses reported as tracked but far away (12.5 m to 10⁵ m from where the hold began, for 1–60 frames,
        /// their time stamps the pose's, none, or 1e308, the frame clock jumping to 1e308 with some of them), and with
        /// one-pose jumps of 1.5–11 m while tracking is steady (beyond 10 m/s over the frames that show the pose), gives the object bit for bit the path it has when those
        /// frames are reported untracked.
        /// </summary>
        [Test]
        public void AnImplausiblePoseIsTreatedAsNotTracked([Range(1, 300)] int seed)
        {
            var rng = new Random(seed);
            string profile = Profiles[seed % Profiles.Count];
            double mass = Mass(rng, seed), standardSpeed = QuestLikeInput.Uniform(rng, 0.3, 1.2);
            var path = ScenarioGenerator.RandomMotion(rng, 4 + 4 * rng.NextDouble());
            path.Hold(1);
            var frames = QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(path);
            var far = (TraceFrame[])frames.Clone();
            var untracked = (TraceFrame[])frames.Clone();
            var notes = new List<string>();
            // One artifact after another, each a second after the last ended: a jump comes after steady tracking (after a
            // loss a hand may have gone further: reach grows with the time it was unseen).
            int from = QuestLikeInput.FrameAt(frames, QuestLikeInput.Uniform(rng, 0.2, 0.8));
            while (from < frames.Length - 2)
            {
                int n;
                double y;
                bool jump = rng.Next(3) == 0;
                if (jump)
                {
                    // One pose (every frame that shows it) jumps 1.5–11 m: within the workspace, beyond any reach over the frames that show it.
                    double poseT = frames[from].PoseTime;
                    n = 0;
                    while (from + n < frames.Length && frames[from + n].PoseTime == poseT) n++;
                    y = frames[from].HandY + (rng.Next(2) == 0 ? 1 : -1) * QuestLikeInput.Uniform(rng, 1.5, 11);
                    notes.Add($"a {y - frames[from].HandY:F2} m jump at {frames[from].Time:F2} s");
                }
                else
                {
                    n = 1 + rng.Next(60);
                    y = frames[0].HandY + (rng.Next(2) == 0 ? 1 : -1) * ScenarioGenerator.LogUniform(rng, 12.5, 99_999.99 - 2);
                    notes.Add($"{n} frames at {y:G6} m from {frames[from].Time:F2} s");
                }
                int timeKind = rng.Next(3);
                bool clockJump = !jump && rng.Next(3) == 0;
                int end = Math.Min(frames.Length - 1, from + n);
                for (int i = from; i < end; i++)
                {
                    double t = clockJump ? 1e308 : frames[i].Time;
                    double poseT = jump || timeKind == 0 ? frames[i].PoseTime : timeKind == 1 ? double.NaN : 1e308;
                    far[i] = new TraceFrame(t, y, true, poseT);
                    untracked[i] = new TraceFrame(t, double.NaN, false, double.NaN);
                }
                if (clockJump) notes[notes.Count - 1] += ", the clock at 1e308";
                from = QuestLikeInput.FrameAt(frames, frames[end].Time + QuestLikeInput.Uniform(rng, 1.0, 2.5));
            }
            string what = $"seed {seed}: {profile}, {mass * 1000:G4} g; " + string.Join("; ", notes);
            var a = Run.Replay(new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile), standardSpeed), far);
            var b = Run.Replay(new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile), standardSpeed), untracked);
            for (int i = 0; i < a.Length; i++)
                if (!a[i].Equals(b[i])) Assert.Fail($"{what}: frame {i} ({frames[i].Time:F3} s): {a[i]} m, untracked {b[i]} m");
        }

        /// <summary>The same in three dimensions, with one or two hands: a hand reported tracked 12.5 m to 10⁵ m from where
        /// the hold began (in any direction, moving 2 mm a frame, so each frame shows a new pose there) is a lost hand, bit for
        /// bit, in x, y and z.</summary>
        [Test]
        public void AnImplausibleHandIsALostHandInThreeDimensions([Range(1, 200)] int seed)
        {
            var rng = new Random(seed);
            string profile = Profiles[seed % Profiles.Count];
            double mass = Mass(rng, seed);
            bool two = rng.Next(2) == 0;
            double rise = QuestLikeInput.Uniform(rng, 0.1, 0.5), side = QuestLikeInput.Uniform(rng, -0.4, 0.4);
            HandPath3D left = (double t, out double x, out double y, out double z) => { x = -0.15 + side * Headset3D.MinJerk(t, 0.5, 1, 0, 1); y = Headset3D.MinJerk(t, 0.5, 1, 0.9, 0.9 + rise); z = 0.3; };
            HandPath3D right = (double t, out double x, out double y, out double z) => { x = 0.15 + side * Headset3D.MinJerk(t, 0.5, 1, 0, 1); y = Headset3D.MinJerk(t, 0.5, 1, 0.9, 0.9 + rise); z = 0.3; };
            var frames = new Headset3D { FrameRate = QuestLikeInput.FrameRates[rng.Next(3)], JitterSd = 0.0015, Seed = seed }.Render(left, two ? right : null, 3);
            var far = Copy(frames);
            var lost = Copy(frames);
            for (int k = 1 + rng.Next(3); k > 0; k--)
            {
                int from = 1 + rng.Next(frames.Count - 2), n = 1 + rng.Next(60), hand = two && rng.Next(2) == 0 ? 2 : 1;
                double d = ScenarioGenerator.LogUniform(rng, 12.5, 99_999.99 - 2), u = rng.NextDouble() * 2 * Math.PI, v = Math.Acos(2 * rng.NextDouble() - 1);
                for (int i = from; i < Math.Min(frames.Count, from + n); i++)
                {
                    var p = hand == 1 ? frames.A[i] : frames.B[i];
                    double wobble = 0.002 * (i - from); // a glitch that stays far away, seen anew each frame
                    var moved = new HandPose(0.15 * (hand == 1 ? -1 : 1) + d * Math.Sin(v) * Math.Cos(u) + wobble, 0.9 + d * Math.Cos(v), 0.3 + d * Math.Sin(v) * Math.Sin(u), true, true, p.PoseTime);
                    if (hand == 1) { far.A[i] = moved; lost.A[i] = HandPose.Lost; } else { far.B[i] = moved; lost.B[i] = HandPose.Lost; }
                }
            }
            var a = Run3D.Of(new WeightSolver3D(WeightModel.FromMass(mass), NamedProfiles.Get(profile)), far);
            var b = Run3D.Of(new WeightSolver3D(WeightModel.FromMass(mass), NamedProfiles.Get(profile)), lost);
            for (int i = 0; i < frames.Count; i++)
                if (!a.X[i].Equals(b.X[i]) || !a.Y[i].Equals(b.Y[i]) || !a.Z[i].Equals(b.Z[i]))
                    Assert.Fail($"seed {seed}: {profile}, {mass * 1000:G4} g, {(two ? "two hands" : "one hand")}: frame {i}: ({a.X[i]}, {a.Y[i]}, {a.Z[i]}) against ({b.X[i]}, {b.Y[i]}, {b.Z[i]})");
        }

        static Headset3D.Frames Copy(Headset3D.Frames f)
            => new Headset3D.Frames { T = f.T, Dt = f.Dt, A = (HandPose[])f.A.Clone(), B = (HandPose[])f.B.Clone() };

        /// <summary>
        /// What moves on its own advances with time, not with new poses: a carry in a random direction (0.1–1.5 m/s, 5–50 cm)
        /// that stops abruptly, after which the pose repeats exactly (its time stamp frozen, or none), ends where the same carry
        /// ends when new poses of the same place keep coming: 2.5 s after the stop within 0.5 mm in x and z and 2 mm in y (the
        /// steady hand takes a repeated pose 0.1 s late, which a heavier object's pace reads as a slower rise), with no
        /// sideways lag left (under 0.5 mm).
        /// </summary>
        [Test]
        public void ARepeatedPoseAdvancesWithTime([Range(1, 300)] int seed)
        {
            var rng = new Random(seed);
            string profile = Profiles[seed % Profiles.Count];
            double mass = Mass(rng, seed);
            double u = rng.NextDouble() * 2 * Math.PI, v = Math.Acos(2 * rng.NextDouble() - 1);
            double ux = Math.Sin(v) * Math.Cos(u), uy = Math.Cos(v), uz = Math.Sin(v) * Math.Sin(u);
            double speed = QuestLikeInput.Uniform(rng, 0.1, 1.5), distance = QuestLikeInput.Uniform(rng, 0.05, 0.5);
            double fps = QuestLikeInput.FrameRates[rng.Next(3)], stop = 0.5 + distance / speed;
            var after = rng.Next(2) == 0 ? AfterTheStop.Frozen : AfterTheStop.NoTimeStamps;
            var repeated = RepeatedPoses.Carry(fps, ux, uy, uz, speed, distance, stop + 2.5, after);
            var fresh = RepeatedPoses.Carry(fps, ux, uy, uz, speed, distance, stop + 2.5, AfterTheStop.NewPoses);
            var a = Run3D.Of(new WeightSolver3D(WeightModel.FromMass(mass), NamedProfiles.Get(profile)), repeated);
            var b = Run3D.Of(new WeightSolver3D(WeightModel.FromMass(mass), NamedProfiles.Get(profile)), fresh);
            int last = a.X.Length - 1;
            string what = $"seed {seed}: {profile}, {mass * 1000:G4} g, {speed:F2} m/s for {distance:F2} m along ({ux:F2}, {uy:F2}, {uz:F2}), {after}";
            Assert.That(a.X[last], Is.EqualTo(b.X[last]).Within(0.0005), what + ": x");
            Assert.That(a.Z[last], Is.EqualTo(b.Z[last]).Within(0.0005), what + ": z");
            Assert.That(a.Y[last], Is.EqualTo(b.Y[last]).Within(0.002), what + ": y");
            double lx = a.FollowedX[last] - a.X[last] - (a.FollowedX[0] - a.X[0]), lz = a.FollowedZ[last] - a.Z[last] - (a.FollowedZ[0] - a.Z[0]);
            Assert.That(Math.Sqrt(lx * lx + lz * lz), Is.LessThan(0.0005), what + ": no sideways lag left");
        }
    }
}
