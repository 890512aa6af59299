using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The speed cap measures strain: how far the hand pulls beyond where an object moving no faster than the user's
    /// rescaled experimental speed of its mass could be. It never moves the object the user sees.
    /// </summary>
    public class SpeedCapTests
    {
        [Test]
        public void TheCapIsTheExperimentalCurveRescaledToTheUser()
        {
            var cap = new SpeedCap();
            var m = WeightModel.FromMass(2);
            Assert.That(cap.CapFor(m, 0.5), Is.EqualTo(2.5 * 0.5 * m.ExperimentalRatio).Within(1e-12));
            Assert.That(cap.CapFor(WeightModel.FromMass(PhysicalConstants.StandardMassKg), 0.5), Is.EqualTo(double.PositiveInfinity), "the golf ball is never capped");
            Assert.That(() => new SpeedCap(0.5), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("headroom"));
            Assert.That(cap.Name, Is.EqualTo("speed-cap"));
        }

        [Test]
        public void ItNeverMovesTheObjectTheUserSees([Values(0.045, 2, 10)] double massKg)
        {
            var frames = Run.Headset(frameRate: 90, jitterSd: 0.001).Render(HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.8, 0.3).Hold(1).MoveTo(1.0, 0.3).Hold(1));
            var with = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper), frames);
            var without = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper.Without<SpeedCap>()), frames);
            Assert.That(with, Is.EqualTo(without));
        }

        [Test]
        public void AYankStrainsByWhatTheCapHoldsBackAndTheStrainFadesAtTheCappedSpeed()
        {
            // 5 kg for a user of 0.5 m/s: v_cap ≈ 0.38 m/s. The hand jumps 0.5 m up in one 30 Hz pose step and stays.
            var s = Run.Solver(5, new WeightProfile("cap", new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new SpeedCap() }), 0.5);
            double cap = s.Constants.CapSpeed, t = 0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 0; i < 4; i++) { t += 1 / 30.0; s.Step(new HandSample(1.0, true, true, t), 1 / 30.0); }
            t += 1 / 30.0;
            s.Step(new HandSample(1.3, true, true, t), 1 / 30.0);
            double target = 1.0 + s.Gain * 0.3; // the weight's own place for the new hand
            Assert.That(s.ObjectY, Is.EqualTo(target).Within(1e-9), "the object the user sees is at once where the weight puts it");
            double allowed = cap * SpeedCap.BurstTime; // what the follower may do in one go
            Assert.That(s.Strain, Is.EqualTo(target - 1.0 - allowed).Within(1e-9), "what the cap could not follow");
            double before = s.Strain;
            t += 0.02;
            s.Step(new HandSample(1.3, true, true, t), 0.02);
            Assert.That(before - s.Strain, Is.EqualTo(cap * 0.02).Within(1e-9), "the strain fades at the capped speed");
            for (int i = 0; i < 200; i++) { t += 0.02; s.Step(new HandSample(1.3, true, true, t), 0.02); }
            Assert.That(s.Strain, Is.EqualTo(0), "and is gone once an object at the capped speed would be there");
        }

        [Test]
        public void MotionTrackingHidIsNoStrain([Values(0.3, 5)] double massKg)
        {
            // 0.3 kg: gain 0.15, so the object the weight puts 7.5 cm higher after the loss is more than a burst away.
            var s = Run.Solver(massKg, new WeightProfile("cap", new WeightEffect[] { new WeightGain(), new SpeedCap() }), 0.5);
            double t = 0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 0; i < 4; i++) { t += 1 / 30.0; s.Step(new HandSample(1.0, true, true, t), 1 / 30.0); }
            for (int i = 0; i < 30; i++) { t += 1 / 30.0; s.Step(HandSample.Lost, 1 / 30.0); }
            t += 1 / 30.0;
            s.Step(new HandSample(1.5, true, true, t), 1 / 30.0); // back 0.5 m higher after a second
            Assert.That(s.Strain, Is.EqualTo(0), "the hand was not seen pulling");
        }

        [Test]
        public void AnObjectMadeHeavyMidHoldIsFollowedAfreshAsAtAGrab()
        {
            // The scene swaps a golf ball (never capped) for 5 kg while the hand rests, and the hand jumps 0.3 m on the next
            // frame. The follower starts where the object is with nothing in hand, as on a hold's first frame; one frame later
            // it may have gone one frame at the cap, not a whole burst. (No weight gain: the object goes where the hand goes.)
            var profile = new WeightProfile("cap", new WeightEffect[] { new SpeedCap() });
            var s = Run.Solver(PhysicalConstants.StandardMassKg, profile, 0.5);
            double t = 0, dt = 1 / 30.0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 0; i < 30; i++) { t += dt; s.Step(new HandSample(1.0, true, true, t), dt); }
            Assert.That(s.Strain, Is.EqualTo(0), "the golf ball is never strained");
            s.Configure(WeightModel.FromMass(5), profile, s.StandardSpeed);
            t += dt;
            s.Step(new HandSample(1.0, true, true, t), dt);
            Assert.That(s.Strain, Is.EqualTo(0), "the swap's frame: the follower starts where the object is");
            double from = s.ObjectY;
            t += dt;
            s.Step(new HandSample(1.3, true, true, t), dt);
            double oneFrame = s.Constants.CapSpeed * Math.Min(dt, s.Profile.Limits.MaxFrameTime); // a frame counts for at most 25 ms
            Assert.That(s.Strain, Is.EqualTo(s.ObjectY - from - oneFrame).Within(1e-12), "one frame's allowance, not a burst");
        }
    }
}
