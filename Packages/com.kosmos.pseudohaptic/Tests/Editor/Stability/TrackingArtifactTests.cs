using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// P12 and issue 22's rules 1 and 5: the offset between hand and object has one source, the weight applied to the hand's
    /// real motion, so anything tracking does leaves no trace. Each case replays one hand path twice through the simulated
    /// Quest (<see cref="QuestLikeInput"/>), clean and with one artifact more, and demands the same object 0.5 s after the
    /// artifact: within 1 mm for the standard weight, 10 mm for heavier objects (bounds of the issue, not of the code), with
    /// no frame's step while it recovers beyond the hand's own largest step in the surrounding 100 ms plus 1 cm.
    /// </summary>
    [TestFixture]
    public class TrackingArtifactTests
    {
        public static readonly string[] Profiles = { "paper", "paper-experiment", "gain", "xyz" };

        enum Artifact { GlitchAtRest, GlitchInMotion, Loss, LowConfidence, Snap }

        /// <summary>One seeded case: a lift (and sometimes a lowering) with an artifact of the given kind.</summary>
        sealed class Case
        {
            public string Description;
            public HandPath Path;
            public Func<HeadsetSimulator> Headset;
            public Action<HeadsetSimulator> AddArtifact;
            public double ArtifactStart, ArtifactEnd, MassKg, StandardSpeed;
            public string Profile;
        }

        static Case Make(int seed)
        {
            var rng = new Random(seed);
            var kind = (Artifact)(seed % 5);
            double rise = QuestLikeInput.Uniform(rng, 0.15, 0.6), seconds = QuestLikeInput.Uniform(rng, 0.4, 2.0);
            double start = 0.8, liftAt = 0.5;
            var path = HandPath.StartAt(start).Hold(liftAt).MoveTo(start + rise, seconds);
            double end = liftAt + seconds;
            bool lowerToo = rng.NextDouble() < 0.3;
            if (lowerToo) { path.MoveTo(start + rise * QuestLikeInput.Uniform(rng, 0.2, 0.8), QuestLikeInput.Uniform(rng, 0.4, 1.5)); end = path.Duration; }
            double at, length = 0, size = 0;
            switch (kind)
            {
                case Artifact.GlitchAtRest: at = end + QuestLikeInput.Uniform(rng, 0.2, 0.8); size = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.2); break;
                case Artifact.GlitchInMotion: at = QuestLikeInput.Uniform(rng, liftAt, end); size = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.2); break;
                case Artifact.Loss: at = QuestLikeInput.Uniform(rng, liftAt - 0.2, end); length = QuestLikeInput.Uniform(rng, 0.05, 1.0); break;
                case Artifact.LowConfidence: at = QuestLikeInput.Uniform(rng, liftAt - 0.2, end); length = QuestLikeInput.Uniform(rng, 0.05, 0.6); break;
                default: at = QuestLikeInput.Uniform(rng, liftAt, end); length = QuestLikeInput.Uniform(rng, 0.1, 0.6); size = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.08); break;
            }
            double artifactEnd = kind == Artifact.Snap ? at + length + 0.1 : at + Math.Max(length, 1.0 / 30);
            path.Hold(Math.Max(0.1, artifactEnd + 0.7 - path.Duration));
            var c = new Case
            {
                Path = path,
                ArtifactStart = at,
                ArtifactEnd = artifactEnd,
                MassKg = QuestLikeInput.Masses[rng.Next(QuestLikeInput.Masses.Length)],
                StandardSpeed = QuestLikeInput.Uniform(rng, 0.3, 1.2),
                Profile = Profiles[rng.Next(Profiles.Length)],
                Headset = () => QuestLikeInput.Headset(new Random(seed * 7919), seed),
            };
            switch (kind)
            {
                case Artifact.GlitchAtRest:
                case Artifact.GlitchInMotion: c.AddArtifact = h => h.Glitch(at, size); break;
                case Artifact.Loss: c.AddArtifact = h => h.Drop(at, length); break;
                case Artifact.LowConfidence: c.AddArtifact = h => h.LowConfidence(at, length); break;
                default: c.AddArtifact = h => h.Drop(at, length).Offset(at + length, 0.1, size); break;
            }
            c.Description = $"seed {seed}: {kind} at {at:F2} s ({length:F2} s, {size * 100:F1} cm), {c.MassKg} kg, {c.Profile}, " +
                $"v_std {c.StandardSpeed:F2}, lift {rise:F2} m in {seconds:F2} s{(lowerToo ? " and a lowering" : "")}";
            return c;
        }

        static double Sign(Random rng) => rng.NextDouble() < 0.5 ? -1 : 1;

        [Test]
        public void ArtifactsLeaveNothingHalfASecondLater([Range(1, 250)] int seed) => ArtifactsLeaveNothingHalfASecondLaterAt(1, seed);

        /// <summary>The same rule at the cue strengths 1/3 and 3 (issue 31), on a subset of the seeds.</summary>
        [Test]
        public void ArtifactsLeaveNothingHalfASecondLaterAtOtherCueStrengths([ValueSource(typeof(CueStrengths), nameof(CueStrengths.Others))] double s, [Range(1, 250, 10)] int seed) => ArtifactsLeaveNothingHalfASecondLaterAt(s, seed);

        static void ArtifactsLeaveNothingHalfASecondLaterAt(double s, int seed)
        {
            var c = Make(seed);
            var clean = c.Headset().Render(c.Path);
            var h = c.Headset();
            c.AddArtifact(h);
            var degraded = h.Render(c.Path);
            var solver = Run.Solver(c.MassKg, NamedProfiles.Get(c.Profile), c.StandardSpeed).At(s);
            var a = Run.Replay(solver, clean);
            var b = Run.Replay(Run.Solver(c.MassKg, NamedProfiles.Get(c.Profile), c.StandardSpeed).At(s), degraded);
            int i = QuestLikeInput.FrameAt(clean, c.ArtifactEnd + 0.5);
            double tolerance = c.MassKg <= PhysicalConstants.StandardMassKg ? 0.001 : 0.010;
            Assert.That(Math.Abs(b[i] - a[i]), Is.LessThanOrEqualTo(tolerance), c.Description + ": 0.5 s after the artifact");
            Assert.That(Math.Abs(Run.Last(b) - Run.Last(a)), Is.LessThanOrEqualTo(tolerance), c.Description + ": at the end");
            double beyond = QuestLikeInput.StepBeyondHand(degraded, b, solver.Gain, c.ArtifactStart, c.ArtifactEnd + 0.5);
            Assert.That(beyond, Is.LessThanOrEqualTo(0.01), c.Description + ": a step beyond the hand's own while it recovers");
        }

        [Test]
        public void TheStandardWeightIsRigidThroughEverything([Range(1, 200)] int seed) => TheStandardWeightIsRigidThroughEverythingAt(1, seed);

        /// <summary>The same rule at the cue strengths 1/3 and 3 (issue 31), on a subset of the seeds.</summary>
        [Test]
        public void TheStandardWeightIsRigidThroughEverythingAtOtherCueStrengths([ValueSource(typeof(CueStrengths), nameof(CueStrengths.Others))] double s, [Range(1, 200, 10)] int seed) => TheStandardWeightIsRigidThroughEverythingAt(s, seed);

        static void TheStandardWeightIsRigidThroughEverythingAt(double s, int seed)
        {
            var c = Make(seed);
            var h = c.Headset();
            c.AddArtifact(h);
            var frames = h.Render(c.Path);
            var y = Run.Replay(Run.Solver(PhysicalConstants.StandardMassKg, NamedProfiles.Get(c.Profile), c.StandardSpeed).At(s), frames);
            double settled = c.ArtifactEnd + 0.3;
            for (int i = 0; i < frames.Length; i++)
            {
                var f = frames[i];
                if (!f.IsUsable || f.LowConfidence) continue; // the hand the solver may follow
                double off = Math.Abs(f.HandY - y[i]);
                bool atRest = f.Time >= settled && Math.Abs(c.Path.HeightAt(f.Time) - c.Path.HeightAt(f.Time - 0.3)) < 1e-9;
                Assert.That(off, Is.LessThanOrEqualTo(atRest ? 0.001 : 0.005), c.Description + $": frame at {f.Time:F3} s");
            }
        }
    }
}
