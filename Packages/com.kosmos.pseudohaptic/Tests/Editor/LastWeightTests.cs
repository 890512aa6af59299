using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// A frame that repeats the last one's hand reuses the last frame's weight (LastWeight) instead of calling the effects
    /// between the estimator and the offset again. It is a saving, not a behaviour: each hold here runs twice, once as the
    /// profile is and once with an extra effect that says it is not a function of the hand (so every frame weighs), and
    /// the two must agree bit for bit on every frame, on Quest-like input with glitches, losses, low confidence, hitches,
    /// a change of mass mid-hold, a hand filter, and poses on a coarse grid (new poses at the last one's height).
    /// The grid is what catches a key that ignores new poses: with <c>!f.NewPose</c> taken out of
    /// <c>LastWeight.Holds</c>, 51 of the 90 grid cases fail and none of the others (a pose on a continuous scale never
    /// repeats the last one's bits).
    /// </summary>
    public class LastWeightTests
    {
        /// <summary>Does nothing, and does not say it is a function of the hand: a profile with it weighs every frame.</summary>
        sealed class WeighEveryFrame : WeightEffect
        {
            public override string Name => "weigh-every-frame";
            public override EffectStage Stage => EffectStage.HandMotion;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
        }

        static IEnumerable<TestCaseData> Cases()
        {
            var profiles = new[]
            {
                NamedProfiles.Paper, NamedProfiles.PaperExperiment, NamedProfiles.Gain,
                NamedProfiles.Paper.With(new HeightDeceleration()), NamedProfiles.Paper.WithHandFilter(new OneEuroFilter()),
            };
            foreach (var profile in profiles)
                foreach (double mass in new[] { 0.02, PhysicalConstants.StandardMassKg, 0.5, 1, 2, 5 })
                    foreach (int rate in new[] { 72, 90, 120 })
                        foreach (bool quantized in new[] { false, true })
                            yield return new TestCaseData(profile, mass, rate, quantized)
                                .SetName("Repeats " + profile.Name + " " + mass + " kg " + rate + " Hz" + (quantized ? " 5 mm poses" : ""));
        }

        [TestCaseSource(nameof(Cases))]
        public void AFrameThatRepeatsTheHandGetsBitForBitTheWeightItWouldCompute(WeightProfile profile, double mass, int rate, bool quantized)
        {
            Assert.That(profile.WeightIsFunctionOfHand, Is.True, "the named profiles reuse the weight");
            var everyFrame = profile.With(new WeighEveryFrame());
            Assert.That(everyFrame.WeightIsFunctionOfHand, Is.False);

            TwinHolds.Run(profile, everyFrame, mass, rate, quantized, rate + (int)(mass * 100), (i, reused, weighed, a, b) =>
            {
                Assert.That(a, Is.EqualTo(b), "object, frame " + i);
                Assert.That(reused.Offset, Is.EqualTo(weighed.Offset), "offset, frame " + i);
                Assert.That(reused.Strain, Is.EqualTo(weighed.Strain), "strain, frame " + i);
                Assert.That(reused.State.Base, Is.EqualTo(weighed.State.Base), "base, frame " + i);
                Assert.That(reused.State.Glide, Is.EqualTo(weighed.State.Glide), "glide, frame " + i);
            });
        }

        [Test]
        public void OnlyAProfileWhoseWeighingEffectsAreAllFunctionsOfTheHandReusesTheWeight()
        {
            Assert.That(NamedProfiles.Xyz.WeightIsFunctionOfHand, Is.True, "hold-stage effects act outside the y pipeline");
            Assert.That(NamedProfiles.Paper.With(new OffsetRelaxation()).WeightIsFunctionOfHand, Is.False, "relaxation reads time");
            Assert.That(new WeightProfile("input-only", new WeightEffect[] { new FrameProbe(), new FloorClamp() }).WeightIsFunctionOfHand,
                Is.True, "input and position effects run every frame anyway");
        }

        /// <summary>Counts its calls; a function of the hand or not, as told.</summary>
        sealed class CountsWeighing : WeightEffect
        {
            readonly bool _ofHand;
            public int Applied;
            public CountsWeighing(bool ofHand) { _ofHand = ofHand; }
            public override string Name => "counts-weighing";
            public override EffectStage Stage => EffectStage.Lift;
            protected override bool IsFunctionOfHand => _ofHand;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => Applied++;
        }

        [Test]
        public void TheWeighingEffectsAreCalledOnNewPosesOnlyNotOnTheFramesThatRepeatTheHand()
        {
            // The saving itself: 30 Hz poses of a rising hand over 90 Hz frames, so two frames in three show the last pose again
            // and reuse its weight. An input effect that never says it is still keeps those frames from being still frames,
            // which would skip the pipeline altogether.
            var counts = new CountsWeighing(ofHand: true);
            var solver = new WeightSolver(WeightModel.FromMass(1), NamedProfiles.Paper.With(counts).With(new NeverStill()));
            solver.BeginHold(1.0, 1.0, 0.0);
            int newPoses = 0;
            double last = double.NaN;
            for (int i = 1; i <= 90; i++)
            {
                double t = Math.Floor(i / 3.0) / 30; // the pose of 30 Hz, shown on three frames
                if (t != last && t > 0) newPoses++;
                last = t;
                solver.Step(new HandSample(1.0 + 0.3 * t, true, true, t), 1 / 90.0);
            }
            Assert.That(newPoses, Is.EqualTo(30));
            Assert.That(counts.Applied, Is.EqualTo(newPoses + 1), "once per new pose, and on the first frame (the grab's pose, shown again)");
        }

        [Test]
        public void AfterTheProfileGainsAnEffectThatIsNotAFunctionOfTheHandAStillHandIsWeighedEveryFrame()
        {
            // The hand rests: frames repeat its sample and are still. The scene then adds an effect that reads time (not a function
            // of the hand): from then on no frame may be skipped, though hand and base are bit for bit as before.
            var solver = new WeightSolver(WeightModel.FromMass(1), NamedProfiles.Paper);
            var pose = new HandSample(1.0, true, true, 0.0);
            solver.BeginHold(1.0, 1.0, 0.0);
            for (int i = 0; i < 30; i++) solver.Step(pose, 1 / 90.0);
            var counts = new CountsWeighing(ofHand: false);
            solver.Configure(solver.Model, NamedProfiles.Paper.With(counts), solver.StandardSpeed);
            for (int i = 0; i < 30; i++) solver.Step(pose, 1 / 90.0);
            Assert.That(counts.Applied, Is.EqualTo(30));
        }
    }
}
