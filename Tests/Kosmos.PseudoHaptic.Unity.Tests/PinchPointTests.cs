using System;
using Kosmos.PseudoHaptic.Meta;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// OVR Hand Pose Source's default position, the pinch point: the midpoint of the thumb and index tips of the hand's
    /// OVRSkeleton, measured in the OVRHand's frame and placed from the tracked transform (the anchor). The wrist, which
    /// it read before, is 14–18 cm from the fingertips in Meta's hand, so a pinch at an object was beyond Pinch Grab's Reach.
    /// </summary>
    public sealed class PinchPointTests : PlayModeFixture
    {
        // The fingertips in the hand's frame (the wrist's), about a curled index finger's reach ahead of it.
        static readonly Vector3 ThumbTip = new Vector3(0.02f, -0.03f, 0.10f), IndexTip = new Vector3(0.02f, -0.01f, 0.10f);
        static readonly Vector3 Pinch = (ThumbTip + IndexTip) * 0.5f;

        /// <summary>As the sample rigs: OVRCameraRig ▸ TrackingSpace ▸ RightHandAnchor ▸ Hand Visual ▸ OVRHandPrefab (OVRHand, OVRSkeleton); the source reads the anchor.</summary>
        (OVRCameraRig rig, Transform visual, OVRHand hand, OVRSkeleton skeleton, OvrHandPoseSource source) Rig()
        {
            var rig = Track(new GameObject("OVRCameraRig")).AddComponent<OVRCameraRig>();
            var (visual, hand, source) = Stock.StockOvrRig.SampleRightHand(rig, skeleton: true);
            return (rig, visual, hand, hand.GetComponent<OVRSkeleton>(), source);
        }

        static void AssertNear(Vector3 actual, Vector3 expected, string what) =>
            Assert.That(Vector3.Distance(actual, expected), Is.LessThan(1e-5f), what + ": " + actual + ", expected " + expected);

        [Test]
        public void WithAHandDrawnOnTheObjectThePinchPointIsTheTrackedOneNotWhereTheOffsetBonesAre()
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            profile.HandDrawing = HandDrawingMode.HandOnObject;
            PseudoHapticWeight box = Box("2 kg", 2f, default, profile);
            var (rig, visual, hand, skeleton, source) = Rig();
            rig.transform.rotation = Quaternion.Euler(0, 90, 0); // the hand's frame is turned: the pinch point is not the wrist plus a world offset
            var grab = source.gameObject.AddComponent<PinchGrab>();
            grab.InjectHand(source);
            grab.HandVisual = visual;
            Frames.Run(1); // the rig's Start
            OvrHands.InitializeSkeleton(skeleton, ThumbTip, IndexTip);

            // The wrist placed so the fingertips meet at the box's centre, then lifted at 0.6 m/s once the pinch closed.
            Vector3 wrist0 = box.Collider.bounds.center - rig.transform.rotation * Pinch;
            int held = 0;
            float worstVisualOffset = 0;
            for (int i = 0; i < 45; i++)
            {
                Vector3 wrist = wrist0 + new Vector3(0, 0.6f * Math.Max(0, i - 5) * Frames.DefaultDuration, 0);
                OvrHands.Track(rig, new Vector3(-0.4f, 1f, 0.3f), rig.trackingSpace.InverseTransformPoint(wrist));
                OvrHands.Report(hand, tracked: true, pinching: i >= 3);
                Frames.Run(1);
                if (grab.Held == null) continue;
                held++;
                Vector3 tracked = rig.rightHandAnchor.TransformPoint(Pinch);
                AssertNear(source.Position, tracked, "frame " + i + ": the tracked pinch point");
                worstVisualOffset = Mathf.Max(worstVisualOffset, Vector3.Distance(visual.position, rig.rightHandAnchor.position));
            }
            Assert.That(held, Is.GreaterThan(30), "frames the box was held");
            Assert.That(worstVisualOffset, Is.GreaterThan(0.01f), "m: 2 kg lags and the hand was drawn on it, its bones with it (the test can fail)");
        }

        [Test]
        public void BeforeTheSkeletonHasItsTipsAndWhileUntrackedItReadsTheWristNeverNaN()
        {
            var (rig, _, hand, skeleton, source) = Rig();
            rig.transform.position = new Vector3(1, 0, 0);
            Frames.Run(1);
            OvrHands.Track(rig, Vector3.zero, new Vector3(0.2f, 1f, 0.3f));
            OvrHands.Report(hand, tracked: true);
            Frames.Run(1);
            Transform anchor = rig.rightHandAnchor;
            AssertNear(source.Position, anchor.position, "the skeleton not initialized (no bones yet): the wrist");

            OvrHands.InitializeSkeleton(skeleton, ThumbTip, IndexTip);
            AssertNear(source.Position, anchor.TransformPoint(Pinch), "initialized: the pinch point");

            OvrHands.Report(hand, tracked: false);
            AssertNear(source.Position, anchor.position, "untracked: the wrist, as before");
            OvrHands.Report(hand, tracked: true);

            Transform thumb = null;
            foreach (OVRBone bone in skeleton.Bones)
                if (bone.Id == OVRSkeleton.BoneId.Hand_ThumbTip) thumb = bone.Transform;
            UnityEngine.Object.DestroyImmediate(thumb.gameObject);
            Vector3 p = source.Position;
            Assert.That(float.IsNaN(p.x) || float.IsNaN(p.y) || float.IsNaN(p.z), Is.False);
            AssertNear(p, anchor.position, "the thumb tip's transform destroyed: the wrist");

            // The runtime's skeleton changed: re-initialized, the missing tip made again, the fingers elsewhere.
            Vector3 thumb2 = new Vector3(0.01f, -0.02f, 0.12f), index2 = new Vector3(0.01f, 0f, 0.12f);
            OvrHands.InitializeSkeleton(skeleton, thumb2, index2);
            AssertNear(source.Position, anchor.TransformPoint((thumb2 + index2) * 0.5f), "the re-initialized skeleton's tips");

            // A skeleton of another bone count replaces every bone (the old ones are destroyed at the frame's end).
            OvrHands.InitializeSkeleton(skeleton, ThumbTip, IndexTip, boneCount: 26);
            Frames.Run(1);
            AssertNear(source.Position, anchor.TransformPoint(Pinch), "the new bones' tips");

            // Hand_ThumbTip and Hand_IndexTip number an OVR hand's bones only.
            OvrHands.InitializeSkeleton(skeleton, ThumbTip, IndexTip, OVRSkeleton.SkeletonType.Body);
            AssertNear(source.Position, anchor.position, "not a hand skeleton: the wrist");
        }

        [Test]
        public void ReadingThePinchPointAllocatesNothing()
        {
            var (rig, _, hand, skeleton, source) = Rig();
            Frames.Run(1);
            OvrHands.Track(rig, Vector3.zero, new Vector3(0.2f, 1f, 0.3f));
            OvrHands.Report(hand, tracked: true);
            OvrHands.InitializeSkeleton(skeleton, ThumbTip, IndexTip);
            Frames.Run(1);
            AssertNear(source.Position, rig.rightHandAnchor.TransformPoint(Pinch), "the pinch point is read (the tips are cached)");
            Vector3 sum = Vector3.zero;
            for (int i = 0; i < 1000; i++) sum += source.Position;
            long allocated = Allocations.OfOneInThree(() => { for (int i = 0; i < 100000; i++) sum += source.Position; });
            Assert.That(allocated, Is.EqualTo(0), "bytes over 100 000 reads");
            Assert.That(float.IsNaN(sum.x), Is.False);
        }
    }
}
