using System.Collections;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>A scripted hand lifts objects of several masses through <see cref="PseudoHapticWeight"/>.</summary>
    public sealed class PseudoHapticWeightTests : PlayModeFixture
    {
        static readonly float[] Masses = { 0.01f, 0.045f, 0.2f, 0.5f, 1f, 2f, 5f };

        [Test]
        public void TheGolfBallStaysWithTheHand()
        {
            PseudoHapticWeight ball = Box("golf ball", (float)PhysicalConstants.StandardMassKg);
            ball.ExplicitStandardSpeed = 0.5f;
            // 0.25 m in 0.75 s: a mean of 0.33 m/s, under the user's standard speed.
            float y = Lift(ball, 0.25f, 0.75f);
            Assert.That(y, Is.EqualTo(0.25f).Within(0.005f));
            Assert.That(ball.Offset, Is.EqualTo(0).Within(0.005));
        }

        [Test]
        public void HeavierObjectsEndLowerAfterTheSameLift()
        {
            float previous = float.PositiveInfinity;
            foreach (float mass in Masses)
            {
                PseudoHapticWeight w = Box(mass + " kg", mass, new Vector3(mass, 0, 0));
                float y = Lift(w, 0.3f, 0.8f);
                Assert.That(y, Is.LessThanOrEqualTo(previous + 1e-4f), mass + " kg ended higher than a lighter object");
                Assert.That(y, Is.GreaterThanOrEqualTo(0f), "below the floor");
                Assert.That(float.IsNaN(y), Is.False);
                previous = y;
                w.EndHold();
            }
            Assert.That(previous, Is.LessThan(0.3f * 0.5f), "5 kg should lag well behind the hand");
        }

        [Test]
        public void LighterThanTheGolfBallLeadsTheHandWithinTheGainCap()
        {
            PseudoHapticWeight feather = Box("10 g", 0.01f);
            float y = Lift(feather, 0.1f, 0.6f);
            Assert.That(y, Is.GreaterThan(0.1f));
            Assert.That(y, Is.LessThanOrEqualTo(0.1f * (float)SolverLimits.Default.MaxGain + 1e-3f));
        }

        [Test]
        public void WhileHeldTheBodyIsKinematicWithoutFallingVelocity()
        {
            PseudoHapticWeight box = Box("box", 1f);
            var body = box.GetComponent<Rigidbody>();
            body.velocity = new Vector3(0, -3f, 0);
            box.Release = ReleaseVelocity.Zero;

            Assert.That(box.BeginHold(box.transform.position + Vector3.up * 0.05f), Is.True);
            Assert.That(body.isKinematic, Is.True);
            box.EndHold();
            Assert.That(body.isKinematic, Is.False);
            Assert.That(body.velocity, Is.EqualTo(Vector3.zero));
        }

        [Test]
        public void ReleaseGivesTheHandsVelocityWhenAskedTo()
        {
            PseudoHapticWeight box = Box("box", 0.2f);
            box.Release = ReleaseVelocity.Hand;
            var hand = new ScriptedHand(box.transform.position);
            Vector3 start = hand.Position;
            Assert.That(box.BeginHold(hand), Is.True);
            for (int i = 1; i <= 30; i++) // 0.33 s rising at 0.5 m/s, released while still rising
            {
                hand.Track(start + new Vector3(0, 0.5f * i * FrameTime, 0), FrameTime);
                box.Step(hand, FrameTime);
            }
            box.EndHold();
            Assert.That(box.GetComponent<Rigidbody>().velocity.y, Is.EqualTo(0.5f).Within(0.1f));
        }

        [Test]
        public void LostTrackingAndGarbagePosesNeverReachTheTransform()
        {
            PseudoHapticWeight box = Box("box", 1f);
            Assert.That(box.BeginHold(box.transform.position), Is.True);
            var nan = new Vector3(float.NaN, float.NaN, float.NaN);
            for (int i = 0; i < 90; i++)
            {
                box.Step(nan, i % 2 == 0, false, double.NaN, FrameTime);
                box.Step(new Vector3(0, 1e30f, 0), true, true, double.NaN, i % 3 == 0 ? 0 : 10f);
                Vector3 p = box.transform.localPosition;
                Assert.That(float.IsNaN(p.y) || float.IsInfinity(p.y), Is.False);
                Assert.That(p.y, Is.GreaterThanOrEqualTo(0f));
            }
        }

        [Test]
        public void DensityTimesVolumeGivesTheMass()
        {
            PseudoHapticWeight box = Box("water cube", 1f);
            box.Mass = MassSource.DensityTimesVolume;
            box.DensityKgPerCubicMetre = 1000f; // 0.1 m cube of water: 1 kg
            Assert.That(box.Configure(), Is.True, box.ConfigurationError);
            Assert.That(box.MassKg, Is.EqualTo(1.0).Within(1e-4));
            Assert.That(box.GetComponent<Rigidbody>().mass, Is.EqualTo(1f).Within(1e-4f));
        }

        [Test]
        public void MassFromTheRigidbody()
        {
            PseudoHapticWeight box = Box("rb", 1f);
            box.GetComponent<Rigidbody>().mass = 2.5f;
            box.Mass = MassSource.Rigidbody;
            Assert.That(box.Configure(), Is.True, box.ConfigurationError);
            Assert.That(box.MassKg, Is.EqualTo(2.5).Within(1e-6));
        }

        [Test]
        public void AnInvalidMassIsReportedNotHeld()
        {
            PseudoHapticWeight box = Box("bad", 1f);
            box.ExplicitMassKg = -1f;
            LogAssert.Expect(LogType.Error, new System.Text.RegularExpressions.Regex("massKg"));
            Assert.That(box.Configure(), Is.False);
            Assert.That(box.ConfigurationError, Does.Contain("massKg"));
            Assert.That(box.BeginHold(Vector3.zero), Is.False);
        }

        [Test]
        public void SwitchingAnEffectDuringAHoldReconfigures()
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.GainName);
            PseudoHapticWeight box = Box("2 kg", 2f, default, profile);
            Assert.That(box.BeginHold(box.transform.position), Is.True);
            double before = box.Gain;
            profile.SetEnabled<WeightGain>(false);
            box.Step(box.transform.position, true, true, double.NaN, FrameTime);
            Assert.That(before, Is.LessThan(1.0));
            Assert.That(box.Gain, Is.EqualTo(1.0));
            Object.DestroyImmediate(profile);
        }

        [TestCase(NamedProfiles.PaperName)]
        [TestCase(NamedProfiles.PaperExperimentName)]
        [TestCase(NamedProfiles.GainName)]
        public void PresetsBuildTheCoresNamedProfiles(string preset)
        {
            PseudoHapticProfile asset = PseudoHapticProfile.CreatePreset(preset);
            Assert.That(asset.Build().ToString(), Is.EqualTo(NamedProfiles.Get(preset).ToString()));
            Object.DestroyImmediate(asset);
        }

        /// <summary>The same lift over real frames: the component in the player loop, as in a scene.</summary>
        [UnityTest]
        public IEnumerator OverRealFramesAHeavyBoxLagsAndTheGolfBallFollows()
        {
            PseudoHapticWeight ball = Box("golf ball", 0.045f, new Vector3(-0.2f, 0, 0));
            PseudoHapticWeight heavy = Box("3 kg", 3f, new Vector3(0.2f, 0, 0));
            var ballHand = new ScriptedHand(ball.transform.position);
            var heavyHand = new ScriptedHand(heavy.transform.position);
            Time.captureDeltaTime = FrameTime; // 90 Hz frames whatever the machine's speed
            Assert.That(ball.BeginHold(ballHand) && heavy.BeginHold(heavyHand), Is.True);

            const float duration = 1.0f, rise = 0.3f;
            float t = 0;
            while (t < duration + 0.3f)
            {
                yield return null;
                float dt = Time.deltaTime;
                t += dt;
                float y = rise * (float)ScriptedHand.MinimumJerk(t / duration);
                ballHand.Track(ball.transform.parent.TransformPoint(new Vector3(-0.2f, y, 0)), dt);
                heavyHand.Track(heavy.transform.parent.TransformPoint(new Vector3(0.2f, y, 0)), dt);
                ball.Step(ballHand, dt);
                heavy.Step(heavyHand, dt);
            }
            Assert.That(ball.transform.localPosition.y, Is.EqualTo(rise).Within(0.01f));
            Assert.That(heavy.transform.localPosition.y, Is.LessThan(ball.transform.localPosition.y - 0.05f));
            ball.EndHold();
            heavy.EndHold();
            Time.captureDeltaTime = 0;
        }
    }
}
