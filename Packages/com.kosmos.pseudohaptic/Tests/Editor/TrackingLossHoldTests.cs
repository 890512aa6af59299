using System.Collections.Generic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The tracking-loss hold frame by frame: what the hold state says about a loss (a scene's effect reads it), the exact end
    /// of the settle time after a loss, and that a settled hand's repeated pose is a still frame again.
    /// </summary>
    public class TrackingLossHoldTests
    {
        /// <summary>Records each frame's Settling flag, after the tracking-loss hold (same stage, later in the list).</summary>
        sealed class SettlingProbe : WeightEffect
        {
            public readonly List<bool> Settling = new List<bool>();
            public override string Name => "settling-probe";
            public override EffectStage Stage => EffectStage.Input;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => Settling.Add(frame.Settling);
        }

        /// <summary>A 1 kg object under the tracking-loss hold of <paramref name="settleTime"/>, the probe after it.</summary>
        static WeightSolver Settling(double settleTime, SettlingProbe probe)
            => new WeightSolver(WeightModel.FromMass(1), new WeightProfile("settle", new WeightEffect[] { new TrackingLossHold(settleTime), probe, new WeightGain() }));

        [Test]
        public void TheHoldStateSaysHowLongTheLossHasLastedAndZeroOnceTracked()
        {
            var s = new WeightSolver(WeightModel.FromMass(1), NamedProfiles.Paper);
            double t = 0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 0; i < 9; i++) { t += 1 / 90.0; s.Step(new HandSample(1.0, true, true, t), 1 / 90.0); }
            for (int i = 1; i <= 27; i++)
            {
                s.Step(HandSample.Lost, 1 / 90.0);
                Assert.That(s.State.LostFor, Is.EqualTo(i / 90.0).Within(1e-12), "lost for " + i + " frames");
            }
            t += 0.3;
            s.Step(new HandSample(1.0, true, true, t), 1 / 90.0);
            Assert.That(s.State.LostFor, Is.EqualTo(0), "tracked again");
        }

        [Test]
        public void PosesCountAgainFromExactlyTheSettleTimeAfterALoss()
        {
            // Frames of 1/64 s and a settle time of 0.125 s, both exact in binary: the 8th usable frame after the loss is the
            // first that counts (the settle time is over), the 7 before it settle.
            var probe = new SettlingProbe();
            var s = Settling(0.125, probe);
            double t = 0, dt = 1 / 64.0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 0; i < 4; i++) { t += dt; s.Step(new HandSample(1.0, true, true, t), dt); }
            for (int i = 0; i < 10; i++) { t += dt; s.Step(HandSample.Lost, dt); }
            probe.Settling.Clear();
            for (int i = 0; i < 10; i++) { t += dt; s.Step(new HandSample(1.0 + 0.001 * i, true, true, t), dt); }
            Assert.That(probe.Settling, Is.EqualTo(new[] { true, true, true, true, true, true, true, false, false, false }));
        }

        [Test]
        public void AHoldBegunTrackedHasNothingToSettleWhateverTheSettleTime()
        {
            // A hold starts settled: with no loss there is nothing to settle, so even the longest settle time (5 s) lets the first
            // frame count.
            var probe = new SettlingProbe();
            var s = Settling(5, probe);
            double t = 0, dt = 1 / 64.0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 1; i <= 10; i++) { t += dt; s.Step(new HandSample(1.0 + 0.001 * i, true, true, t), dt); }
            Assert.That(probe.Settling, Is.All.False);
        }

        [Test]
        public void OnceSettledAfterALossARepeatedPoseIsAStillFrameAgain()
        {
            var counts = new CountsPipelineFrames();
            var s = new WeightSolver(WeightModel.FromMass(1), NamedProfiles.Paper.With(counts));
            var pose = new HandSample(1.0, true, true, 0.0);
            s.BeginHold(1.0, 1.0, 0.0);
            for (int i = 0; i < 10; i++) s.Step(HandSample.Lost, 1 / 90.0);
            pose = new HandSample(1.0, true, true, 0.2);
            for (int i = 0; i < 30; i++) s.Step(pose, 1 / 90.0); // 0.33 s of one pose: settled after the default 0.16 s
            int before = counts.Calls;
            for (int i = 0; i < 30; i++) s.Step(pose, 1 / 90.0);
            // Settled, the same pose again runs the pipeline only when the repeat time (0.1 s) has passed: 3 of 30 frames.
            Assert.That(counts.Calls - before, Is.LessThanOrEqualTo(4), "still frames, not the pipeline every frame");
        }
    }
}
