using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;
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

            var path = HandPath.StartAt(0.9).Hold(0.5).MoveTo(1.35, 0.7).Hold(0.4).MoveTo(1.2, 0.2).MoveTo(1.35, 0.2).Hold(0.6)
                .MoveTo(0.7, 0.9).Hold(0.5).MoveTo(1.5, 0.3).Hold(1.0).MoveTo(0.9, 1.0).Hold(0.5);
            var frames = new HeadsetSimulator
            {
                FrameRate = rate, FrameTimeWobble = 0.1, JitterSd = 0.0015, Seed = rate + (int)(mass * 100), GlitchChance = 0.03,
                LowConfidenceAboveSpeed = 0.8,
            }.Drop(2.0, 0.3).Glitch(3.1, 0.15).LowConfidence(4.0, 0.2).Render(path);

            var reused = new WeightSolver(WeightModel.FromMass(mass), profile);
            var weighed = new WeightSolver(WeightModel.FromMass(mass), everyFrame);
            reused.BeginHold(frames[0].HandY, frames[0].HandY - 0.02, frames[0].PoseTime);
            weighed.BeginHold(frames[0].HandY, frames[0].HandY - 0.02, frames[0].PoseTime);
            for (int i = 1; i < frames.Length; i++)
            {
                double dt = i % 97 == 0 ? 0.2 : frames[i].Time - frames[i - 1].Time; // now and then a hitch
                if (i == frames.Length / 2)
                {
                    // Mid-hold: another mass (a second hand joining), then back.
                    reused.Configure(WeightModel.FromMass(mass * 0.5), profile, 0.5);
                    weighed.Configure(WeightModel.FromMass(mass * 0.5), everyFrame, 0.5);
                }
                if (i == frames.Length * 3 / 4)
                {
                    reused.Configure(WeightModel.FromMass(mass), profile, 0.5);
                    weighed.Configure(WeightModel.FromMass(mass), everyFrame, 0.5);
                }
                var sample = frames[i].ToSample();
                // Poses on a 5 mm grid: new poses that repeat the last one's height, whose median may still move.
                if (quantized) sample = new HandSample(System.Math.Round(sample.Y * 200) / 200, sample.IsTracked, sample.IsHighConfidence, sample.PoseTime);
                double a = reused.Step(sample, dt), b = weighed.Step(sample, dt);
                Assert.That(a, Is.EqualTo(b), "object, frame " + i);
                Assert.That(reused.Offset, Is.EqualTo(weighed.Offset), "offset, frame " + i);
                Assert.That(reused.Strain, Is.EqualTo(weighed.Strain), "strain, frame " + i);
                Assert.That(reused.State.Base, Is.EqualTo(weighed.State.Base), "base, frame " + i);
                Assert.That(reused.State.Glide, Is.EqualTo(weighed.State.Glide), "glide, frame " + i);
            }
        }

        [Test]
        public void OnlyAProfileWhoseWeighingEffectsAreAllFunctionsOfTheHandReusesTheWeight()
        {
            Assert.That(NamedProfiles.Xyz.WeightIsFunctionOfHand, Is.True, "hold-stage effects act outside the y pipeline");
            Assert.That(NamedProfiles.Paper.With(new OffsetRelaxation()).WeightIsFunctionOfHand, Is.False, "relaxation reads time");
            Assert.That(new WeightProfile("input-only", new WeightEffect[] { new FrameProbe(), new FloorClamp() }).WeightIsFunctionOfHand,
                Is.True, "input and position effects run every frame anyway");
        }
    }
}
