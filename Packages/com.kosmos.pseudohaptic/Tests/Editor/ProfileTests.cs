using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    public class ProfileTests
    {
        [Test]
        public void NamedProfilesAreWhatTheyClaim()
        {
            Assert.That(NamedProfiles.Names, Is.EqualTo(new[] { "paper", "paper-experiment", "gain", "xyz", "paper-literal" }));
            foreach (var name in NamedProfiles.Names) Assert.That(NamedProfiles.Get(name).Name, Is.EqualTo(name));
            Assert.That(NamedProfiles.Paper.Has<WeightGain>() && NamedProfiles.Paper.Has<ExperimentalBlend>() && NamedProfiles.Paper.Has<OffsetCorrection>() && NamedProfiles.Paper.Has<FloorClamp>(), Is.True);
            Assert.That(NamedProfiles.Gain.Has<ExperimentalBlend>(), Is.False);
        }

        [Test]
        public void UnknownProfileNamesTheValueAndTheChoices()
        {
            var e = Assert.Throws<ArgumentException>(() => NamedProfiles.Get("heavy"));
            Assert.That(e.ParamName, Is.EqualTo("profile"));
            Assert.That(e.Message, Does.Contain("heavy").And.Contain("paper-experiment"));
        }

        [Test]
        public void EffectsRunInStageOrderWhateverOrderTheyAreGiven()
        {
            var p = new WeightProfile("mixed", new WeightEffect[] { new FloorClamp(), new OffsetCorrection(), new MotionDeadband(), new TrackingLossHold() });
            Assert.That(p.Effects[0], Is.InstanceOf<TrackingLossHold>());
            Assert.That(p.Effects[1], Is.InstanceOf<MotionDeadband>());
            Assert.That(p.Effects[3], Is.InstanceOf<FloorClamp>());
        }

        [Test]
        public void AnEffectListedTwiceIsRejected()
        {
            var e = Assert.Throws<ArgumentException>(() => new WeightProfile("x", new WeightEffect[] { new FloorClamp(), new FloorClamp(1) }));
            Assert.That(e.Message, Does.Contain("floor-clamp"));
        }

        [Test]
        public void WithReplacesAndWithoutRemoves()
        {
            var p = NamedProfiles.Paper.With(new OffsetCorrection(threshold: 0.1), "tight");
            Assert.That(p.Find<OffsetCorrection>().Threshold, Is.EqualTo(0.1));
            Assert.That(p.Effects.Count, Is.EqualTo(NamedProfiles.Paper.Effects.Count));
            Assert.That(NamedProfiles.Paper.Find<OffsetCorrection>().Threshold, Is.EqualTo(0.2), "the preset is untouched");
            Assert.That(p.Without<OffsetCorrection>().Has<OffsetCorrection>(), Is.False);
        }

        [Test]
        public void ReconfiguringDuringAHoldContinuesFromWhereTheObjectIs()
        {
            var s = new WeightSolver(WeightModel.FromMass(1));
            s.BeginHold(1, 1, 0);
            s.Step(new HandSample(1.1, true, true, 0.1), 0.1);
            double y = s.ObjectY;
            s.Configure(WeightModel.FromMass(0.045), NamedProfiles.Gain, 0.5);
            Assert.That(s.ObjectY, Is.EqualTo(y));
            // Now a golf ball: it moves with the hand, and the offset the 1 kg weight left glides away at the glide speed.
            double glidePerFrame = SolverLimits.Default.GlideSpeed * SolverLimits.Default.MaxFrameTime;
            s.Step(new HandSample(1.2, true, true, 0.13), 0.03);
            Assert.That(s.ObjectY - y, Is.EqualTo(0.1 + glidePerFrame).Within(1e-9));
            for (int i = 0; i < 20; i++) s.Step(new HandSample(1.2, true, true, 0.13 + 0.03 * (i + 1)), 0.03);
            Assert.That(s.ObjectY, Is.EqualTo(1.2).Within(1e-12), "then it is in the hand");
        }

        [Test]
        public void EveryEffectHasItsDocumentedName()
        {
            // The names profiles print and the docs and the Playground sample's switches use (ALGORITHM.md, Samples~/Playground).
            var names = new (WeightEffect effect, string name)[]
            {
                (new TrackingLossHold(), "tracking-loss-hold"), (new MotionDeadband(), "motion-deadband"), (new WeightGain(), "weight-gain"),
                (new ExperimentalBlend(), "experimental-blend"), (new FasterMovesFurther(), "faster-moves-further"), (new SpeedCap(), "speed-cap"),
                (new LoweringGuard(), "lowering-guard"), (new OffsetCorrection(), "offset-correction"), (new OffsetRelaxation(), "offset-relaxation"),
                (new FloorClamp(), "floor-clamp"), (new HeightDeceleration(), "height-deceleration"), (new LateralInertia(), "lateral-inertia"),
                (new TwoHands(), "two-hands"), (new BreakAway(0.3), "break-away"),
            };
            foreach (var (effect, name) in names) Assert.That(effect.Name, Is.EqualTo(name), effect.GetType().Name);
        }
    }
}
