using System.Collections;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>A scripted pinching hand grabs, lifts and releases objects through <see cref="PinchGrab"/>.</summary>
    public sealed class PinchGrabTests : PlayModeFixture
    {
        PinchGrab Grabber(ScriptedHand hand)
        {
            var go = Track(new GameObject("hand"));
            go.SetActive(false); // driven by Tick in [Test]s, not by LateUpdate
            var grab = go.AddComponent<PinchGrab>();
            grab.InjectHand(hand);
            return grab;
        }

        static void Frames(PinchGrab grab, ScriptedHand hand, Vector3 from, Vector3 to, float seconds)
        {
            int n = Mathf.CeilToInt(seconds / FrameTime);
            for (int i = 1; i <= n; i++)
            {
                hand.Track(Vector3.Lerp(from, to, (float)ScriptedHand.MinimumJerk(i / (double)n)), FrameTime);
                grab.Tick(FrameTime);
            }
        }

        [Test]
        public void APinchNearAnObjectLiftsItAndOpeningTheHandDropsIt()
        {
            PseudoHapticWeight box = Box("2 kg", 2f);
            Vector3 grabPoint = box.transform.position + new Vector3(0, 0.05f, 0); // the box's centre
            var hand = new ScriptedHand(grabPoint);
            PinchGrab grab = Grabber(hand);

            grab.Tick(FrameTime);
            Assert.That(grab.Held, Is.Null, "no pinch, no grab");
            hand.IsPinching = true;
            grab.Tick(FrameTime);
            Assert.That(grab.Held, Is.SameAs(box));
            Assert.That(box.GetComponent<Rigidbody>().isKinematic, Is.True);

            Vector3 lifted = grabPoint + new Vector3(0.1f, 0.3f, 0);
            Frames(grab, hand, grabPoint, lifted, 0.8f);
            Frames(grab, hand, lifted, lifted, 0.3f);
            float y = box.transform.localPosition.y;
            Assert.That(y, Is.GreaterThan(0f).And.LessThan(0.3f * 0.6f), "2 kg lags the hand");
            Assert.That(box.transform.position.x, Is.EqualTo(lifted.x).Within(1e-4f), "x follows the hand");

            hand.IsPinching = false;
            for (int i = 0; i < 9; i++) grab.Tick(FrameTime); // 0.1 s: the pinch opens after its hysteresis
            Assert.That(grab.Held, Is.Null);
            Assert.That(box.IsHeld, Is.False);
            Assert.That(box.GetComponent<Rigidbody>().isKinematic, Is.False);
        }

        [Test]
        public void ThePinchTakesTheNearestObjectInReach()
        {
            PseudoHapticWeight near = Box("near", 1f, new Vector3(0, 0, 0));
            PseudoHapticWeight far = Box("far", 1f, new Vector3(0.12f, 0, 0));
            var hand = new ScriptedHand(near.transform.position + new Vector3(0.03f, 0.05f, 0)) { IsPinching = true };
            PinchGrab grab = Grabber(hand);
            grab.Tick(FrameTime);
            Assert.That(grab.Held, Is.SameAs(near));
            Assert.That(far.IsHeld, Is.False);
        }

        [Test]
        public void OutOfReachNothingIsGrabbed()
        {
            PseudoHapticWeight box = Box("box", 1f);
            var hand = new ScriptedHand(box.transform.position + new Vector3(0, 0.5f, 0)) { IsPinching = true };
            PinchGrab grab = Grabber(hand);
            grab.Tick(FrameTime);
            Assert.That(grab.Held, Is.Null);
        }

        [Test]
        public void LosingTrackingHoldsTheObjectThenReleasesIt()
        {
            PseudoHapticWeight box = Box("box", 0.5f);
            var hand = new ScriptedHand(box.transform.position + new Vector3(0, 0.05f, 0)) { IsPinching = true };
            PinchGrab grab = Grabber(hand);
            grab.Tick(FrameTime);
            Assert.That(grab.Held, Is.SameAs(box));

            hand.IsTracked = false;
            hand.Position = new Vector3(float.NaN, float.NaN, float.NaN);
            float y = box.transform.localPosition.y;
            for (int i = 0; i < 45; i++) grab.Tick(FrameTime); // 0.5 s
            Assert.That(grab.Held, Is.SameAs(box), "held through a short loss");
            Assert.That(box.transform.localPosition.y, Is.EqualTo(y), "and not moved");
            for (int i = 0; i < 60; i++) grab.Tick(FrameTime);
            Assert.That(grab.Held, Is.Null, "released after a long one");
        }

        /// <summary>In the player loop: the grab runs in LateUpdate and the hand moves between frames.</summary>
        [UnityTest]
        public IEnumerator InThePlayerLoopHeavierBoxesEndLower()
        {
            float[] masses = { 0.045f, 0.5f, 2f };
            var heights = new float[masses.Length];
            Time.captureDeltaTime = FrameTime;
            for (int k = 0; k < masses.Length; k++)
            {
                PseudoHapticWeight box = Box(masses[k] + " kg", masses[k], new Vector3(0.3f * k, 0, 0));
                Vector3 start = box.transform.position + new Vector3(0, 0.05f, 0);
                var hand = new ScriptedHand(start) { IsPinching = true };
                var go = Track(new GameObject("hand " + k));
                go.AddComponent<PinchGrab>().InjectHand(hand);

                float t = 0;
                while (t < 1.2f)
                {
                    yield return null;
                    t += Time.deltaTime;
                    hand.Track(start + new Vector3(0, 0.25f * (float)ScriptedHand.MinimumJerk(t / 0.9), 0), Time.deltaTime);
                }
                heights[k] = box.transform.localPosition.y;
                hand.IsPinching = false;
                for (int i = 0; i < 9; i++) yield return null; // 0.1 s: the pinch opens after its hysteresis
                Assert.That(box.IsHeld, Is.False);
            }
            Time.captureDeltaTime = 0;
            Assert.That(heights[0], Is.EqualTo(0.25f).Within(0.015f), "the golf ball follows the hand");
            Assert.That(heights[1], Is.LessThan(heights[0]));
            Assert.That(heights[2], Is.LessThan(heights[1]));
        }
    }
}
