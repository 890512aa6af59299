using System;
using System.Reflection;
using Kosmos.PseudoHaptic.Meta;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 34 item 3: OVRCameraRig re-poses its hand anchors in Application.onBeforeRender (late latching), after every
    /// LateUpdate, so a hand visual offset in LateUpdate alone would be drawn where the late pose puts the anchor plus the
    /// LateUpdate's offset: off the object by the late pose's step. The visual is placed again after the rig's
    /// before-render update (PinchGrab.BeforeRenderOrder), so a hand drawn on the object stays on it.
    /// </summary>
    public sealed class DrawnHandBeforeRenderTests : PlayModeFixture
    {
        /// <summary>The OVR runtime: a pose in Update, a newer one (the pose predicted for display) before the frame renders.</summary>
        [DefaultExecutionOrder(-200)]
        sealed class LatePoses : MonoBehaviour
        {
            public OVRCameraRig Rig;
            public OVRHand Hand;
            public Func<double, Vector3> Path;
            public double Ahead = 0.012; // s: the render pose is this much newer
            public Vector3 RenderPose;

            void OnEnable() => Application.onBeforeRender += NewerPose;
            void OnDisable() => Application.onBeforeRender -= NewerPose;

            void Update()
            {
                OvrHands.Track(Rig, new Vector3(-0.4f, 1f, 0.3f), Path(Time.timeAsDouble));
                OvrHands.Report(Hand, tracked: true, pinching: Time.timeAsDouble > 0.05);
            }

            [BeforeRenderOrder(-10)] // before the rig's own before-render update (0), as the runtime's pose is
            void NewerPose()
            {
                RenderPose = Path(Time.timeAsDouble + Ahead);
                OvrHands.Track(Rig, new Vector3(-0.4f, 1f, 0.3f), RenderPose);
            }
        }

        (OVRCameraRig rig, Transform visual, PinchGrab grab, LatePoses runtime, PseudoHapticWeight box) Scene(HandDrawingMode drawing)
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            profile.HandDrawing = drawing;
            PseudoHapticWeight box = Box("2 kg", 2f, default, profile);
            Vector3 start = box.Collider.bounds.center;

            // The sample rigs' layout: RightHandAnchor ▸ Hand Visual ▸ OVRHandPrefab; the source reads the anchor.
            var rig = Track(new GameObject("OVRCameraRig")).AddComponent<OVRCameraRig>();
            var (visual, hand, source) = Stock.StockOvrRig.SampleRightHand(rig, skeleton: false);
            GameObject handGo = hand.gameObject;
            PinchGrab grab = handGo.AddComponent<PinchGrab>(); // subscribes to onBeforeRender before the rig does (its Start)
            grab.InjectHand(source);
            grab.HandVisual = visual;
            LatePoses runtime = Track(new GameObject("OVR runtime")).AddComponent<LatePoses>();
            runtime.Rig = rig;
            runtime.Hand = hand;
            runtime.Path = t => start + new Vector3(0, (float)(0.6 * Math.Max(0, t - 0.1)), 0); // 0.6 m/s up after the grab
            return (rig, visual, grab, runtime, box);
        }

        [Test]
        public void AHandDrawnOnTheObjectStaysOnItWhenTheRigRePosesTheAnchorBeforeRendering()
        {
            var (rig, visual, grab, runtime, box) = Scene(HandDrawingMode.HandOnObject);
            Vector3? grip = null;
            double worst = 0, lateStep = 0;
            for (int i = 0; i < 45; i++)
            {
                Frames.Run(1);
                if (grab.Held == null) continue;
                Assert.That(Vector3.Distance(rig.rightHandAnchor.position, runtime.RenderPose), Is.LessThan(1e-5f), "the rig drew the hand at the render pose");
                lateStep = Math.Max(lateStep, runtime.RenderPose.y - runtime.Path(Time.timeAsDouble).y);
                Vector3 boxToVisual = box.transform.position - visual.position;
                grip ??= boxToVisual; // the grab's offset, hand to object
                worst = Math.Max(worst, Vector3.Distance(boxToVisual, grip.Value));
            }
            Assert.That(grab.Held, Is.SameAs(box));
            Assert.That(lateStep, Is.GreaterThan(0.005), "m: the before-render pose is a step ahead of the update's (the test can fail)");
            Assert.That(worst, Is.LessThan(1e-4), "m: the drawn hand kept the grab's offset from the object every frame");
            Assert.That(Vector3.Distance(visual.position, rig.rightHandAnchor.position), Is.GreaterThan(0.01f), "2 kg lags: the visual was moved off the tracked hand");
        }

        [Test]
        public void AHandDrawnTrueStaysOnTheReposedAnchor()
        {
            var (rig, visual, grab, _, _) = Scene(HandDrawingMode.HandTrue);
            Frames.Run(30);
            Assert.That(grab.Held, Is.Not.Null);
            Assert.That(Vector3.Distance(visual.position, rig.rightHandAnchor.position), Is.LessThan(1e-6f));
        }

        [Test]
        public void PlacingTheVisualBeforeRenderAllocatesNothing()
        {
            var (_, _, grab, _, _) = Scene(HandDrawingMode.HandOnObject);
            Frames.Run(20);
            Assert.That(grab.Held, Is.Not.Null);
            var place = (Action)Delegate.CreateDelegate(typeof(Action), grab, typeof(PinchGrab).GetMethod("PlaceVisualBeforeRender", BindingFlags.Instance | BindingFlags.NonPublic));
            Assert.That(place.Method.GetCustomAttribute<BeforeRenderOrderAttribute>().order, Is.GreaterThan(0), "after OVRCameraRig's before-render update, which has no order (0)");
            for (int i = 0; i < 1000; i++) place();
            long allocated = Allocations.OfOneInThree(() => { for (int i = 0; i < 100000; i++) place(); });
            Assert.That(allocated, Is.EqualTo(0), "bytes over 100 000 placements");
        }
    }
}
