using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.XRI;
using NUnit.Framework;
using Unity.XR.CoreUtils;
using UnityDouble;
using UnityEngine;
using UnityEngine.XR.Interaction.Toolkit;
using UnityEngine.XR.Interaction.Toolkit.Transformers;
#if KOSMOS_XRI_3
using UnityEngine.InputSystem;
using UnityEngine.XR.Interaction.Toolkit.Interactables;
using UnityEngine.XR.Interaction.Toolkit.Interactors;
using Controller = UnityEngine.InputSystem.XR.TrackedPoseDriver;
#else
using UnityEngine.XR;
using Controller = UnityEngine.XR.Interaction.Toolkit.ActionBasedController;
#endif

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 34 item 1: the XR Interaction Toolkit grab transformer on an XRGrabInteractable of the double (XRI 2.5.4's call
    /// order), held by direct interactors under an XR Origin as the Starter Assets rig lays them out. The same file runs
    /// under XRI 3 (Tests/Kosmos.PseudoHaptic.Unity.Xri3.Tests, KOSMOS_XRI_3: the double's XRI 3.0.8 declarations, whose
    /// call order is 2.5.4's): there each controller is posed by an Input System TrackedPoseDriver, as in XRI 3's Starter
    /// Assets rig, instead of an ActionBasedController. Each lift is run twice
    /// in the same frames: through XRI, and by a twin box driven straight through the weight's own grab API
    /// (BeginHold/Step/EndHold, what Pinch Grab calls) with the same hands; the two must agree to 0.01 mm, so the
    /// transformer adds no grab rule of its own. Absolute checks (the box rose, lagged, held still, fell) ride along.
    /// </summary>
    public sealed class XriTransformerTests : PlayModeFixture
    {
        const float Tolerance = 1e-5f; // m: float round-off between two identical computations, far below a frame's motion

        sealed class Rig
        {
            public Transform Origin, Offset;
            public Controller Left, Right;
            public XRDirectInteractor LeftHand, RightHand;
        }

        /// <summary>XR Origin ▸ Camera Offset ▸ Left/Right Controller (ActionBasedController + XRDirectInteractor).</summary>
        Rig MakeRig()
        {
            var rig = new Rig();
            GameObject origin = Track(new GameObject("XR Origin"));
            var xrOrigin = origin.AddComponent<XROrigin>();
            var offset = new GameObject("Camera Offset");
            offset.transform.SetParent(origin.transform, false);
            xrOrigin.Origin = origin;
            xrOrigin.CameraFloorOffsetObject = offset;
            rig.Origin = origin.transform;
            rig.Offset = offset.transform;
            (rig.Left, rig.LeftHand) = MakeController("Left Controller", offset.transform);
            (rig.Right, rig.RightHand) = MakeController("Right Controller", offset.transform);
            return rig;
        }

        static (Controller, XRDirectInteractor) MakeController(string name, Transform parent)
        {
            var go = new GameObject(name);
            go.transform.SetParent(parent, false);
            Controller c = go.AddComponent<Controller>();
#if KOSMOS_XRI_3
            // As XRI 3's Starter Assets bind it: position and tracking state of the XR controller (here reported by the test).
            c.positionInput = new InputActionProperty(new InputAction("Position", expectedControlType: "Vector3"));
            c.trackingStateInput = new InputActionProperty(new InputAction("Tracking State", expectedControlType: "Integer"));
#endif
            return (c, go.AddComponent<XRDirectInteractor>());
        }

        /// <summary>What the XR runtime reports for a controller this frame: its pose in the tracking space, and whether it is tracked.</summary>
        static void Report(Controller c, Vector3 trackingSpacePosition, bool tracked = true)
        {
#if KOSMOS_XRI_3
            InputActions.Report(c.positionInput.action, trackingSpacePosition);
            InputActions.Report(c.trackingStateInput.action, tracked ? 3 : 0); // InputTrackingState Position | Rotation, or None
#else
            XRControllerState s = c.currentControllerState;
            s.position = trackingSpacePosition;
            s.inputTrackingState = tracked ? InputTrackingState.Position | InputTrackingState.Rotation : InputTrackingState.None;
            s.isTracked = tracked;
#endif
        }

        (PseudoHapticWeight weight, XRGrabInteractable grab, PseudoHapticGrabTransformer transformer) Grabbable(float massKg, PseudoHapticProfile profile = null)
        {
            PseudoHapticWeight weight = Box("Box", massKg, default, profile);
            var transformer = weight.gameObject.AddComponent<PseudoHapticGrabTransformer>();
            return (weight, weight.GetComponent<XRGrabInteractable>(), transformer);
        }

        /// <summary>
        /// The twin: a second box driven through the weight's own API by the same controllers, in the same frames (after the
        /// controllers wrote their poses, as XRI's manager runs), with the tracked flags the test reports.
        /// </summary>
        [DefaultExecutionOrder(-50)]
        sealed class Twin : MonoBehaviour
        {
            public PseudoHapticWeight Weight;
            public Transform RigSpace;
            readonly List<(int id, Transform hand)> _held = new List<(int, Transform)>(), _joining = new List<(int, Transform)>();
            readonly List<int> _leaving = new List<int>();
            public readonly Dictionary<Transform, bool> Tracked = new Dictionary<Transform, bool>();
            FrameClock _clock;

            public void Grab(int id, Component hand) => _joining.Add((id, hand.transform));
            public void Release(int id) => _leaving.Add(id);

            void Update()
            {
                foreach (int id in _leaving)
                {
                    _held.RemoveAll(h => h.id == id);
                    Weight.EndHold(id);
                }
                _leaving.Clear();
                foreach (var (id, hand) in _joining)
                {
                    if (Weight.Hold.HandCount == 0)
                    {
                        Weight.Rig = RigSpace;
                        _clock.Start(Time.timeAsDouble);
                    }
                    Assert.That(Weight.BeginHold(id, hand.position, double.NaN, RigidbodyControl.External), Is.True);
                    _held.Add((id, hand));
                }
                _joining.Clear();
                if (_held.Count == 0) return;
                float dt = _clock.Delta(Time.timeAsDouble);
                foreach (var (id, hand) in _held)
                {
                    bool tracked = !Tracked.TryGetValue(hand, out bool t) || t;
                    Weight.Step(id, hand.position, tracked, tracked, double.NaN, dt, grabMovesHorizontal: true);
                }
            }
        }

        Twin MakeTwin(PseudoHapticWeight like, float massKg, PseudoHapticProfile profile, Rig rig)
        {
            PseudoHapticWeight twin = Box("Twin", massKg, like.transform.localPosition, profile);
            twin.transform.SetParent(null, true); // XRI unparents a grabbed object: the twin lives where it does
            var driver = twin.gameObject.AddComponent<Twin>();
            driver.Weight = twin;
            driver.RigSpace = rig.Offset;
            return driver;
        }

        static float Smooth(float u)
        {
            u = Mathf.Clamp01(u);
            return u * u * u * (10 - 15 * u + 6 * u * u);
        }

        static void AssertSame(PseudoHapticWeight xri, Twin twin, string when)
        {
            Assert.That(Vector3.Distance(xri.transform.position, twin.Weight.transform.position), Is.LessThanOrEqualTo(Tolerance), when + ": position");
            Assert.That(Quaternion.Angle(xri.transform.rotation, twin.Weight.transform.rotation), Is.LessThanOrEqualTo(0.01f), when + ": rotation");
        }

        [Test]
        public void AddingTheComponentBringsTheInteractableAndRegistersInBothListsAtStart()
        {
            var (_, grab, transformer) = Grabbable(1f);
            Assert.That(grab, Is.Not.Null, "RequireComponent added the XR Grab Interactable");
            Assert.That(grab.singleGrabTransformersCount, Is.Zero, "XRI's transformers register in Start");
            Frames.Run(1);
            Assert.That(grab.singleGrabTransformersCount, Is.EqualTo(1));
            Assert.That(grab.multipleGrabTransformersCount, Is.EqualTo(1));
            Assert.That(grab.GetSingleGrabTransformerAt(0), Is.SameAs(transformer));
            Assert.That(grab.GetMultipleGrabTransformerAt(0), Is.SameAs(transformer));
            Assert.That(grab.attachEaseInTime, Is.Zero, "linked: no ease-in lag the solver does not know");
            Assert.That(grab.smoothPosition || grab.smoothRotation, Is.False);
        }

        [Test]
        public void ALiftThroughXriIsTheWeightsOwnLift()
        {
            Rig rig = MakeRig();
            var (weight, grab, _) = Grabbable(2f);
            Twin twin = MakeTwin(weight, 2f, null, rig);
            Vector3 start = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
            Report(rig.Right, start);
            Frames.Run(1);
            grab.interactionManager.SelectEnter(rig.RightHand, grab);
            twin.Grab(1, rig.Right);
            Assert.That(weight.transform.parent, Is.Null, "XRI unparents what it grabs");
            float y0 = weight.transform.position.y, handRise = 0.3f, maxLag = 0;
            for (int i = 1; i <= 120; i++)
            {
                Vector3 hand = start + new Vector3(0.05f * Smooth(i / 80f), handRise * Smooth(i / 80f), 0);
                Report(rig.Right, hand);
                Frames.Run(1);
                AssertSame(weight, twin, "frame " + i);
                maxLag = Mathf.Max(maxLag, rig.Offset.TransformPoint(hand).y - 0.05f - weight.transform.position.y);
            }
            Assert.That(weight.IsHeld, Is.True);
            float rise = weight.transform.position.y - y0;
            Assert.That(rise, Is.GreaterThan(0.05f), "the box rose with the hand (0.3 m)");
            Assert.That(maxLag, Is.GreaterThan(0.01f), "2 kg lags the hand by more than a centimetre on the way");
            Assert.That(grab.GetComponent<Rigidbody>().isKinematic, Is.True, "XRI holds the body kinematic (Instantaneous movement)");
        }

        /// <summary>The hand moves in real time: the same lift through XRI moves the box the same way at any Time.timeScale.</summary>
        [Test]
        public void TheGamesTimeScaleDoesNotChangeALift()
        {
            float[] Lift(float scale, float x)
            {
                Time.timeScale = scale;
                try
                {
                    Rig rig = MakeRig();
                    rig.Origin.position = new Vector3(x, 0, 0);
                    PseudoHapticWeight weight = Box("Box", 2f, new Vector3(x, 0, 0));
                    weight.gameObject.AddComponent<PseudoHapticGrabTransformer>();
                    var grab = weight.GetComponent<XRGrabInteractable>();
                    Vector3 start = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
                    Report(rig.Right, start);
                    Frames.Run(1);
                    grab.interactionManager.SelectEnter(rig.RightHand, grab);
                    var path = new float[110];
                    for (int i = 0; i < path.Length; i++)
                    {
                        Report(rig.Right, start + new Vector3(0, 0.25f * Smooth(Mathf.Min(1f, i / 80f)), 0));
                        Frames.Run(1);
                        path[i] = weight.transform.position.y;
                    }
                    grab.interactionManager.SelectExit(rig.RightHand, grab);
                    return path;
                }
                finally
                {
                    Time.timeScale = 1;
                }
            }
            float[] normal = Lift(1f, 0);
            Assert.That(normal[normal.Length - 1] - normal[0], Is.GreaterThan(0.05f), "the box rose");
            Assert.That(Lift(0.5f, 2), Is.EqualTo(normal).Within(1e-5f), "slow motion");
            Assert.That(Lift(0f, 4), Is.EqualTo(normal).Within(1e-5f), "paused");
        }

        [Test]
        public void ATwoHandLiftIsTheWeightsTwoHandHold()
        {
            Rig rig = MakeRig();
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            var (weight, grab, transformer) = Grabbable(3f, profile);
            Twin twin = MakeTwin(weight, 3f, profile, rig);
            Vector3 centre = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
            Vector3 l0 = centre + new Vector3(-0.06f, 0, 0), r0 = centre + new Vector3(0.06f, 0, 0);
            Report(rig.Left, l0);
            Report(rig.Right, r0);
            Assert.That(grab.selectMode, Is.EqualTo(InteractableSelectMode.Single), "XRI's default");
            Frames.Run(1);
            // Single would let the second hand take the box from the first: the transformer links it (in its Start) Multiple.
            Assert.That(grab.selectMode, Is.EqualTo(InteractableSelectMode.Multiple));
            grab.interactionManager.SelectEnter(rig.LeftHand, grab);
            grab.interactionManager.SelectEnter(rig.RightHand, grab);
            twin.Grab(1, rig.Left);
            twin.Grab(2, rig.Right);
            float y0 = weight.transform.position.y;
            for (int i = 1; i <= 120; i++)
            {
                Vector3 up = new Vector3(0, 0.25f * Smooth(i / 80f), 0);
                Report(rig.Left, l0 + up);
                Report(rig.Right, r0 + up);
                Frames.Run(1);
                Assert.That(weight.Hold.HandCount, Is.EqualTo(2), "frame " + i);
                AssertSame(weight, twin, "frame " + i);
            }
            Assert.That(transformer.Hands.Count, Is.EqualTo(2));
            Assert.That(weight.transform.position.y - y0, Is.GreaterThan(0.05f), "both hands lifted it (0.25 m)");
        }

        [Test]
        public void AHandChangeKeepsTheHoldAndNeverStepsTheBox()
        {
            Rig rig = MakeRig();
            var (weight, grab, _) = Grabbable(1f);
            Twin twin = MakeTwin(weight, 1f, null, rig);
            int began = 0, ended = 0;
            void Began(PseudoHapticWeight w) { if (w == weight) began++; }
            void Ended(PseudoHapticWeight w) { if (w == weight) ended++; }
            PseudoHapticWeight.HoldBegan += Began;
            PseudoHapticWeight.HoldEnded += Ended;
            try
            {
                Vector3 centre = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
                Vector3 l0 = centre + new Vector3(-0.05f, 0, 0), r0 = centre + new Vector3(0.05f, 0, 0);
                Report(rig.Left, l0);
                Report(rig.Right, r0);
                Frames.Run(1);
                grab.interactionManager.SelectEnter(rig.LeftHand, grab);
                twin.Grab(1, rig.Left);
                Vector3 last = weight.transform.position;
                float largestStep = 0;
                for (int i = 1; i <= 150; i++)
                {
                    if (i == 40)
                    {
                        grab.interactionManager.SelectEnter(rig.RightHand, grab);
                        twin.Grab(2, rig.Right);
                    }
                    if (i == 80)
                    {
                        grab.interactionManager.SelectExit(rig.LeftHand, grab);
                        twin.Release(1);
                    }
                    Vector3 up = new Vector3(0, 0.3f * Smooth(i / 130f), 0);
                    Report(rig.Left, l0 + up);
                    Report(rig.Right, r0 + up);
                    Frames.Run(1);
                    AssertSame(weight, twin, "frame " + i);
                    largestStep = Mathf.Max(largestStep, Vector3.Distance(last, weight.transform.position));
                    last = weight.transform.position;
                    if (i == 60) Assert.That(weight.Hold.HandCount, Is.EqualTo(2), "the right hand joined");
                    if (i == 100) Assert.That(weight.Hold.HandCount, Is.EqualTo(1), "the left hand left");
                }
                Assert.That(weight.IsHeld, Is.True);
                Assert.That(began, Is.EqualTo(1), "one hold from the first hand to the last");
                Assert.That(ended, Is.Zero);
                // The hand's fastest frame is 0.3 m × 1.875 (minimum jerk's peak speed) / 130 frames ≈ 4.3 mm: no jump at a handover.
                Assert.That(largestStep, Is.LessThan(0.3f * 1.875f / 130f * 1.5f), "m per frame");
            }
            finally
            {
                PseudoHapticWeight.HoldBegan -= Began;
                PseudoHapticWeight.HoldEnded -= Ended;
            }
        }

        /// <summary>
        /// Switching the transformer or the weight off mid-grab ends the weight's hold (their OnDisable); XRI keeps the
        /// selection and calls no OnGrabCountChanged when they are switched on again, so the transformer itself takes the
        /// selecting hands back on its next Dynamic phase: the box follows the hand again, rather than hanging where it was.
        /// </summary>
        [Test]
        public void SwitchedOffAndOnMidGrabTheHoldResumes([Values(true, false)] bool theTransformer)
        {
            Rig rig = MakeRig();
            var (weight, grab, transformer) = Grabbable(1f);
            Vector3 start = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
            Report(rig.Right, start);
            Frames.Run(1);
            grab.interactionManager.SelectEnter(rig.RightHand, grab);
            Frames.Run(10);
            Assert.That(weight.IsHeld, Is.True);
            Behaviour toggled = theTransformer ? transformer : (Behaviour)weight;
            toggled.enabled = false;
            Frames.Run(5);
            Assert.That(weight.IsHeld, Is.False, "switched off: no hold");
            toggled.enabled = true;
            Frames.Run(1);
            Assert.That(weight.IsHeld, Is.True, "held again");
            Assert.That(transformer.Hands.Count, Is.EqualTo(1));
            float y0 = weight.transform.position.y;
            for (int i = 1; i <= 120; i++)
            {
                Report(rig.Right, start + new Vector3(0, 0.2f * Smooth(Mathf.Min(1, i / 60f)), 0));
                Frames.Run(1);
            }
            // 1 kg lags the hand (up 8.4 cm of its 20 when the run ends); a box left hanging would not rise at all.
            Assert.That(weight.transform.position.y - y0, Is.InRange(0.05f, 0.2f), "the box follows the hand's 0.2 m rise again");
        }

        [Test]
        public void ADropEndsTheHoldRestoresTheParentAndTheBodyAndLeavesTheBoxAlone()
        {
            Rig rig = MakeRig();
            var (weight, grab, transformer) = Grabbable(1f);
            Transform table = weight.transform.parent;
            Vector3 start = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
            Report(rig.Right, start);
            Frames.Run(1);
            grab.interactionManager.SelectEnter(rig.RightHand, grab);
            for (int i = 1; i <= 60; i++)
            {
                Report(rig.Right, start + new Vector3(0, 0.2f * Smooth(i / 50f), 0));
                Frames.Run(1);
            }
            Assert.That(weight.IsHeld, Is.True);
            grab.interactionManager.SelectExit(rig.RightHand, grab);
            Assert.That(weight.IsHeld, Is.False, "OnDrop ended the hold");
            Assert.That(transformer.Hands.Count, Is.Zero);
            Assert.That(weight.transform.parent, Is.SameAs(table), "XRI gave the parent back");
            Assert.That(grab.GetComponent<Rigidbody>().isKinematic, Is.False, "and the body");
            Vector3 dropped = weight.transform.position;
            for (int i = 1; i <= 30; i++)
            {
                Report(rig.Right, start + new Vector3(0, 0.2f + 0.01f * i, 0));
                Frames.Run(1);
            }
            Assert.That(weight.transform.position, Is.EqualTo(dropped), "nothing moves a dropped box (the double has no gravity)");
        }

        [Test]
        public void ALostHandHoldsTheBoxStillAndTheLiftGoesOnWhenItReturns()
        {
            Rig rig = MakeRig();
            var (weight, grab, _) = Grabbable(1f);
            Twin twin = MakeTwin(weight, 1f, null, rig);
            Vector3 start = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
            Report(rig.Right, start);
            Frames.Run(1);
            grab.interactionManager.SelectEnter(rig.RightHand, grab);
            twin.Grab(1, rig.Right);
            Vector3 atLoss = default;
            for (int i = 1; i <= 150; i++)
            {
                bool lost = i >= 40 && i < 70; // a third of a second without tracking, mid-lift
                twin.Tracked[rig.Right.transform] = !lost;
                Report(rig.Right, start + new Vector3(0, 0.3f * Smooth(i / 120f), 0), tracked: !lost);
                Frames.Run(1);
                AssertSame(weight, twin, "frame " + i);
                if (i == 40) atLoss = weight.transform.position;
                if (lost) Assert.That(Vector3.Distance(weight.transform.position, atLoss), Is.LessThanOrEqualTo(Tolerance), "frame " + i + ": held still while lost");
            }
            Assert.That(weight.IsHeld, Is.True, "a short loss keeps the grab (XRI's selection is the interactor's)");
            Assert.That(weight.transform.position.y - atLoss.y, Is.GreaterThan(0.05f), "the lift went on after the hand returned");
        }

        /// <summary>Issue 26 with XRI: the XR Origin walks, turns and teleports mid-lift; in its frame the box's path is the standing-still one.</summary>
        /// <remarks>
        /// Before rendering, Unity runs the weight's re-placing (order 0) before XRI's manager ([BeforeRenderOrder(100)]); the
        /// double runs handlers in subscription order, so the case "box first" subscribes the weight first (Unity's order) and
        /// the others the manager first: the box ends where the rig carries it either way.
        /// </remarks>
        [TestCase(false, false, TestName = "The rig's motion carries an XRI-held box rigidly: rig moved between frames")]
        [TestCase(true, false, TestName = "The rig's motion carries an XRI-held box rigidly: rig moved in LateUpdate, XRI's before-render first")]
        [TestCase(true, true, TestName = "The rig's motion carries an XRI-held box rigidly: rig moved in LateUpdate, the weight's before-render first")]
        public void TheRigsMotionCarriesTheBoxRigidly(bool late, bool boxFirst)
        {
            List<Vector3> Lift(bool move)
            {
                PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
                PseudoHapticWeight early = boxFirst ? Box("Box", 2f, default, profile) : null; // subscribes to onBeforeRender before any XRI object
                Rig rig = MakeRig();
                PseudoHapticWeight weight = early != null ? early : Box("Box", 2f, default, profile);
                weight.gameObject.AddComponent<PseudoHapticGrabTransformer>();
                var grab = weight.GetComponent<XRGrabInteractable>();
                Mover mover = rig.Origin.gameObject.AddComponent<Mover>();
                Vector3 start = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
                Report(rig.Right, start);
                Frames.Run(1);
                grab.interactionManager.SelectEnter(rig.RightHand, grab);
                var path = new List<Vector3>();
                for (int i = 1; i <= 120; i++)
                {
                    if (move)
                    {
                        int k = i - 1; // the rig starts moving once the grab has begun (in frame 1)
                        Vector3 p = new Vector3(0.02f * k, 0, 0.01f * k) + (k >= 50 ? new Vector3(5, 0.5f, -3) : Vector3.zero); // walk, then a teleport
                        Quaternion r = Quaternion.Euler(0, 1.5f * k + (k >= 80 ? 45 : 0), 0); // turn, then a snap turn
                        if (late) { mover.Position = p; mover.Rotation = r; mover.Armed = true; }
                        else { rig.Origin.position = p; rig.Origin.rotation = r; }
                    }
                    Report(rig.Right, start + new Vector3(0.03f * Smooth(i / 90f), 0.25f * Smooth(i / 90f), 0));
                    Frames.Run(1);
                    path.Add(rig.Offset.InverseTransformPoint(weight.transform.position));
                }
                Assert.That(weight.IsHeld, Is.True);
                UnityEngine.Object.DestroyImmediate(weight.gameObject);
                UnityEngine.Object.DestroyImmediate(rig.Origin.gameObject);
                UnityEngine.Object.DestroyImmediate(grab.interactionManager.gameObject); // the next run makes its own, subscribing when it does
                Frames.ResetClock();
                return path;
            }
            var still = Lift(false);
            var moved = Lift(true);
            Assert.That(still[still.Count - 1].y - still[0].y, Is.GreaterThan(0.05f), "the box rose");
            for (int i = 0; i < still.Count; i++)
                Assert.That(Vector3.Distance(still[i], moved[i]), Is.LessThanOrEqualTo(0.001f), "frame " + (i + 1));
        }

        /// <summary>Moves the rig in LateUpdate, after XRI's Dynamic phase placed the box (a late locomotion).</summary>
        sealed class Mover : MonoBehaviour
        {
            public Vector3 Position;
            public Quaternion Rotation = Quaternion.identity;
            public bool Armed;

            void LateUpdate()
            {
                if (!Armed) return;
                transform.position = Position;
                transform.rotation = Rotation;
            }
        }

        [Test]
        public void ABreakAwayCancelsBothSelectionsOnceAndTheBodyIsLetGo()
        {
            Rig rig = MakeRig();
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            profile.SetEnabled<BreakAway>(true);
            profile.SetEnabled<OffsetCorrection>(false); // which would keep the lag under the break-away distance
            var (weight, grab, _) = Grabbable(5f, profile);
            int began = 0, ended = 0;
            void Began(PseudoHapticWeight w) => began++;
            void Ended(PseudoHapticWeight w) => ended++;
            PseudoHapticWeight.HoldBegan += Began;
            PseudoHapticWeight.HoldEnded += Ended;
            try
            {
                Vector3 centre = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
                Report(rig.Left, centre + new Vector3(-0.04f, 0, 0));
                Report(rig.Right, centre + new Vector3(0.04f, 0, 0));
                Frames.Run(1);
                grab.interactionManager.SelectEnter(rig.LeftHand, grab);
                grab.interactionManager.SelectEnter(rig.RightHand, grab);
                for (int i = 1; i <= 60 && grab.isSelected; i++)
                {
                    Vector3 up = new Vector3(0, 0.8f * Mathf.Clamp01(i / 36f), 0);
                    Report(rig.Left, centre + new Vector3(-0.04f, 0, 0) + up);
                    Report(rig.Right, centre + new Vector3(0.04f, 0, 0) + up);
                    Frames.Run(1);
                }
            }
            finally
            {
                PseudoHapticWeight.HoldBegan -= Began;
                PseudoHapticWeight.HoldEnded -= Ended;
            }
            Assert.That(grab.isSelected, Is.False, "every selection cancelled");
            Assert.That(rig.LeftHand.hasSelection || rig.RightHand.hasSelection, Is.False);
            Assert.That(weight.IsHeld, Is.False);
            Assert.That(began, Is.EqualTo(1), "the hold began once");
            Assert.That(ended, Is.EqualTo(1), "and ended once");
            Assert.That(grab.GetComponent<Rigidbody>().isKinematic, Is.False, "XRI let the body go: it falls");
        }

        [Test]
        public void ProcessAllocatesNothing()
        {
            Rig rig = MakeRig();
            var (weight, grab, transformer) = Grabbable(1f);
            Vector3 centre = rig.Offset.InverseTransformPoint(weight.transform.position + new Vector3(0, 0.05f, 0));
            Report(rig.Left, centre);
            Report(rig.Right, centre + new Vector3(0.1f, 0, 0));
            Frames.Run(1);
            grab.interactionManager.SelectEnter(rig.LeftHand, grab);
            grab.interactionManager.SelectEnter(rig.RightHand, grab);
            Frames.Run(3);
            Assert.That(weight.Hold.HandCount, Is.EqualTo(2));
            Pose pose = grab.GetTargetPose();
            Vector3 scale = Vector3.one;
            Transform left = rig.Left.transform;
            void Frames1000()
            {
                for (int i = 0; i < 1000; i++)
                {
                    left.localPosition = centre + new Vector3(0, 0.0001f * (i % 100), 0);
                    transformer.Process(grab, XRInteractionUpdateOrder.UpdatePhase.Dynamic, ref pose, ref scale);
                    transformer.Process(grab, XRInteractionUpdateOrder.UpdatePhase.OnBeforeRender, ref pose, ref scale);
                }
            }
            Frames1000(); // warm
            long allocated = Allocations.OfOneInThree(Frames1000);
            Assert.That(allocated, Is.Zero, "bytes allocated by 2000 Process calls (Dynamic and OnBeforeRender, two hands)");
        }
    }
}
