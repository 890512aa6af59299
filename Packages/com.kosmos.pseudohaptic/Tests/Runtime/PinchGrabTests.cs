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

        [Test]
        public void TwoHandsHoldOneBoxUntilTheLastLetsGo()
        {
            PseudoHapticWeight box = Box("box", 1f);
            var left = new ScriptedHand(box.transform.position + new Vector3(-0.04f, 0.05f, 0)) { IsPinching = true };
            var right = new ScriptedHand(box.transform.position + new Vector3(0.04f, 0.05f, 0)) { IsPinching = true };
            PinchGrab l = Grabber(left), r = Grabber(right);
            l.Tick(FrameTime);
            r.Tick(FrameTime);
            Assert.That(l.Held, Is.SameAs(box));
            Assert.That(r.Held, Is.SameAs(box), "the second hand joins");
            Assert.That(box.Hold.HandCount, Is.EqualTo(2));
            left.IsPinching = false;
            for (int i = 0; i < 9; i++) { l.Tick(FrameTime); r.Tick(FrameTime); }
            Assert.That(l.Held, Is.Null);
            Assert.That(box.IsHeld, Is.True, "still held by the right hand");
            right.IsPinching = false;
            for (int i = 0; i < 9; i++) { l.Tick(FrameTime); r.Tick(FrameTime); }
            Assert.That(box.IsHeld, Is.False);
            Assert.That(box.GetComponent<Rigidbody>().isKinematic, Is.False);
        }

        /// <summary>Issue 24: two hands' x/z came from whichever hand ticked last; now from both, in either order.</summary>
        [TestCase(true)]
        [TestCase(false)]
        public void TwoHandsMoveXAndZByTheirMeanWhicheverTicksLast(bool leftFirst)
        {
            PseudoHapticWeight box = Box("box", 1f);
            Vector3 start = box.transform.position;
            Vector3 l0 = start + new Vector3(-0.04f, 0.05f, 0), r0 = start + new Vector3(0.04f, 0.05f, 0);
            var left = new ScriptedHand(l0) { IsPinching = true };
            var right = new ScriptedHand(r0) { IsPinching = true };
            PinchGrab l = Grabber(left), r = Grabber(right);
            l.Tick(FrameTime);
            r.Tick(FrameTime);
            for (int i = 0; i < 45; i++) // the left hand slides 10 cm sideways, the right one stays
            {
                left.Track(l0 + new Vector3(0.1f, 0, 0.06f), FrameTime);
                right.Track(r0, FrameTime);
                if (leftFirst) { l.Tick(FrameTime); r.Tick(FrameTime); }
                else { r.Tick(FrameTime); l.Tick(FrameTime); }
            }
            Assert.That(box.transform.position.x, Is.EqualTo(start.x + 0.05f).Within(1e-4f), "x: half of one hand's move");
            Assert.That(box.transform.position.z, Is.EqualTo(start.z + 0.03f).Within(1e-4f), "z: half of one hand's move");
        }

        [Test]
        public void ABreakAwayReleasesBothHandsAndTheBoxFalls()
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            profile.SetEnabled<BreakAway>(true); // 0.25 m: under xyz's offset correction, of strain (a yank, not a distance)
            PseudoHapticWeight box = Box("5 kg", 5f, default, profile);
            Vector3 l0 = box.transform.position + new Vector3(-0.04f, 0.05f, 0), r0 = box.transform.position + new Vector3(0.04f, 0.05f, 0);
            var left = new ScriptedHand(l0) { IsPinching = true };
            var right = new ScriptedHand(r0) { IsPinching = true };
            PinchGrab l = Grabber(left), r = Grabber(right);
            l.Tick(FrameTime);
            r.Tick(FrameTime);
            Assert.That(box.Hold.HandCount, Is.EqualTo(2));
            // A yank: 1 m in 0.3 s, both hands.
            int n = Mathf.CeilToInt(0.6f / FrameTime);
            for (int i = 1; i <= n && box.IsHeld; i++)
            {
                float u = (float)ScriptedHand.MinimumJerk(i / (0.3 / FrameTime));
                left.Track(l0 + new Vector3(0, 1.0f * u, 0), FrameTime);
                right.Track(r0 + new Vector3(0, 1.0f * u, 0), FrameTime);
                l.Tick(FrameTime);
                r.Tick(FrameTime);
            }
            l.Tick(FrameTime);
            r.Tick(FrameTime);
            Assert.That(l.Grab.LastEnd, Is.EqualTo(GrabEnd.BrokeAway));
            Assert.That(r.Grab.LastEnd, Is.EqualTo(GrabEnd.BrokeAway));
            Assert.That(l.Held == null && r.Held == null && !box.IsHeld, Is.True);
            Assert.That(box.GetComponent<Rigidbody>().isKinematic, Is.False, "the Rigidbody falls");
        }

        [Test]
        public void WithLateralInertiaXAndZAreTheSolversAndTrailTheHand()
        {
            PseudoHapticWeight box = Box("2 kg", 2f, default, PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName));
            Vector3 start = box.transform.position + new Vector3(0, 0.05f, 0);
            var hand = new ScriptedHand(start) { IsPinching = true };
            PinchGrab grab = Grabber(hand);
            grab.Tick(FrameTime);
            Vector3 side = start + new Vector3(0.4f, 0, 0);
            Frames(grab, hand, start, side, 0.35f);
            Assert.That(box.transform.position.x, Is.LessThan(side.x - 0.01f), "2 kg trails a fast sideways carry");
            Frames(grab, hand, side, side, 1.5f);
            Assert.That(box.transform.position.x, Is.EqualTo(side.x).Within(0.005f), "and arrives under the hand");
        }

        /// <summary>A 5 kg box under a hand-on-object profile, and a pinching hand 5 cm above its pivot.</summary>
        (PseudoHapticWeight Box, Vector3 Start, ScriptedHand Hand) FiveKiloBoxDrawnWithTheHandOnIt()
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            profile.HandDrawing = HandDrawingMode.HandOnObject;
            PseudoHapticWeight box = Box("5 kg", 5f, default, profile);
            Vector3 start = box.transform.position + new Vector3(0, 0.05f, 0);
            return (box, start, new ScriptedHand(start) { IsPinching = true });
        }

        [Test]
        public void AHandOnObjectProfileDrawsTheHandVisualAtTheObjectAndReturnsIt()
        {
            var (box, start, hand) = FiveKiloBoxDrawnWithTheHandOnIt();
            PinchGrab grab = Grabber(hand);
            var visual = Track(new GameObject("Hand Visual")).transform;
            visual.SetParent(grab.transform, false);
            grab.HandVisual = visual;
            grab.Tick(FrameTime);
            Vector3 top = start + new Vector3(0, 0.2f, 0);
            Frames(grab, hand, start, top, 0.6f);
            Frames(grab, hand, top, top, 0.2f);
            float lag = box.transform.position.y - (hand.Position.y - 0.05f);
            Assert.That(lag, Is.LessThan(-0.02f), "5 kg lags a 0.2 m lift");
            Assert.That(visual.localPosition.y, Is.EqualTo(lag).Within(1e-4f), "the visual is drawn where the object is");
            hand.IsPinching = false;
            Frames(grab, hand, top, top, 0.35f); // opens after 50 ms, back within 200 ms
            Assert.That(grab.Held, Is.Null);
            Assert.That(visual.localPosition.y, Is.EqualTo(0f).Within(1e-6f), "back on the tracked hand");
        }

        /// <summary>
        /// Switched off mid-hold, the grab no longer draws the hand visual (neither in LateUpdate nor before rendering): it
        /// stayed where the last lag put it, centimetres off the real hand, for as long as the grab stayed off.
        /// </summary>
        [Test]
        public void AGrabSwitchedOffMidHoldPutsTheHandVisualBackOnTheTrackedHand()
        {
            var (box, start, hand) = FiveKiloBoxDrawnWithTheHandOnIt();
            PinchGrab grab = Track(new GameObject("hand")).AddComponent<PinchGrab>(); // active: switching it off calls OnDisable
            grab.InjectHand(hand);
            var visual = Track(new GameObject("Hand Visual")).transform;
            visual.SetParent(grab.transform, false);
            visual.localPosition = new Vector3(0, 0, 0.01f); // the visual's own rest pose under the grab
            grab.HandVisual = visual;
            grab.Tick(FrameTime);
            Vector3 top = start + new Vector3(0, 0.2f, 0);
            Frames(grab, hand, start, top, 0.6f);
            Assert.That(visual.localPosition.y, Is.LessThan(-0.02f), "drawn at the lagging object");
            grab.enabled = false;
            Assert.That(grab.Held, Is.Null);
            Assert.That(visual.localPosition, Is.EqualTo(new Vector3(0, 0, 0.01f)), "back at its rest pose");
        }

        /// <summary>
        /// The player's hand moves in real time whatever the game's clock does (slow motion, a pause menu at timeScale 0):
        /// the same real lift moves the box the same way, frame by frame, at any <c>Time.timeScale</c>. On the game's
        /// clock a hand at half speed read as twice as fast (the lightest gain), and at 0 nothing moved.
        /// </summary>
        [UnityTest]
        public IEnumerator TheGamesTimeScaleDoesNotChangeALift()
        {
            float[] scales = { 1f, 0.5f, 0f };
            var paths = new float[scales.Length][];
            Time.captureDeltaTime = FrameTime;
            try
            {
                for (int k = 0; k < scales.Length; k++)
                {
                    Time.timeScale = scales[k];
                    PseudoHapticWeight box = Box("2 kg at " + scales[k], 2f, new Vector3(0.3f * k, 0, 0));
                    Vector3 start = box.transform.position + new Vector3(0, 0.05f, 0);
                    var hand = new ScriptedHand(start) { IsPinching = true };
                    Track(new GameObject("hand " + k)).AddComponent<PinchGrab>().InjectHand(hand);
                    paths[k] = new float[110];
                    for (int i = 0; i < paths[k].Length; i++)
                    {
                        yield return null;
                        hand.Track(start + new Vector3(0, 0.25f * (float)ScriptedHand.MinimumJerk(Mathf.Min(1f, i / 80f)), 0), Time.unscaledDeltaTime);
                        paths[k][i] = box.transform.localPosition.y;
                    }
                    hand.IsPinching = false;
                    for (int i = 0; i < 9; i++) yield return null;
                }
            }
            finally
            {
                Time.timeScale = 1;
                Time.captureDeltaTime = 0;
            }
            Assert.That(paths[0][paths[0].Length - 1], Is.GreaterThan(0.05f), "the box rose");
            for (int k = 1; k < scales.Length; k++)
                Assert.That(paths[k], Is.EqualTo(paths[0]).Within(1e-5f), "timeScale " + scales[k]);
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
