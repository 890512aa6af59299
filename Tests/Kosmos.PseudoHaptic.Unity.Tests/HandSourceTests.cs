using Kosmos.PseudoHaptic.Meta;
using Kosmos.PseudoHaptic.XRHands;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;
using UnityEngine.XR.Hands;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The OVR and XR Hands pose sources under the SDK doubles (issue 24's two source defects).</summary>
    public sealed class HandSourceTests
    {
        /// <summary>OVRCameraRig ▸ TrackingSpace ▸ RightHandAnchor ▸ Hand Visual (offset) ▸ OVRHand, as the sample rigs build it.</summary>
        static (OVRCameraRig rig, OVRHand hand, Transform visual, OvrHandPoseSource source) Rig()
        {
            var rig = new GameObject("OVRCameraRig").AddComponent<OVRCameraRig>();
            var visual = new GameObject("Hand Visual").transform;
            visual.SetParent(rig.rightHandAnchor, false);
            var handGo = new GameObject("OVRHandPrefab");
            handGo.transform.SetParent(visual, false);
            OVRHand hand = handGo.AddComponent<OVRHand>();
            var source = handGo.AddComponent<OvrHandPoseSource>();
            source.Tracked = rig.rightHandAnchor;
            return (rig, hand, visual, source);
        }

        [Test]
        public void ThePointerPoseIsPlacedThroughTheTrackingSpaceNotThroughTheOffsetHandVisual()
        {
            var (rig, hand, visual, source) = Rig();
            source.Source = OvrHandPoseSource.PositionSource.PointerPose;
            rig.transform.position = new Vector3(5, 0, 0);
            OvrHands.Report(hand, tracked: true);
            OvrHands.ReportPointer(hand, new Vector3(0.2f, 1.0f, 0.3f));
            OvrHands.Track(rig, Vector3.zero, new Vector3(0.25f, 1.0f, 0.3f));
            Frames.Run(1);
            visual.localPosition = new Vector3(0, -0.08f, 0); // the hand drawn on a lagging object
            Vector3 p = source.Position;
            Assert.That(Vector3.Distance(p, new Vector3(5.2f, 1.0f, 0.3f)), Is.LessThan(1e-5f), "the tracked pointer, whatever the visual's offset: " + p);
            Assert.That(source.Rig, Is.SameAs(rig.trackingSpace));
        }

        [Test]
        public void TheRunningHandSubsystemIsReadWhenAnotherIsListedFirst()
        {
            // A project with two hand subsystems (a simulator's beside OpenXR's) lists a stopped one first: the hand read as
            // untracked for good (the first in the list was taken, running or not).
            XRHandSubsystem stopped = XRHandsRuntime.Start(), running = XRHandsRuntime.Start();
            stopped.Stop();
            var source = new GameObject("hand").AddComponent<XRHandPoseSource>();
            source.HandSide = Handedness.Right;
            XRHandsRuntime.Joint(running, Handedness.Right, XRHandJointID.Wrist, new Vector3(0, 1, 0.3f), XRHandJointTrackingState.Pose);
            Frames.Run(1);
            Assert.That(source.Subsystem, Is.SameAs(running));
            Assert.That(source.IsTracked, Is.True);
            Assert.That(Vector3.Distance(source.Position, new Vector3(0, 1, 0.3f)), Is.LessThan(1e-5f));
            stopped.Destroy();
            running.Destroy();
        }

        [Test]
        public void ThePinchPointsConfidenceIsTheFingertipsNotTheWrists()
        {
            XRHandSubsystem subsystem = XRHandsRuntime.Start();
            var source = new GameObject("hand").AddComponent<XRHandPoseSource>();
            source.HandSide = Handedness.Right;
            source.PositionFrom = XRHandPoseSource.PositionJoint.PinchPoint;
            const XRHandJointTrackingState high = XRHandJointTrackingState.Pose | XRHandJointTrackingState.HighFidelityPose;
            XRHandsRuntime.Joint(subsystem, Handedness.Right, XRHandJointID.Wrist, new Vector3(0, 1, 0.3f), high);
            XRHandsRuntime.Joint(subsystem, Handedness.Right, XRHandJointID.ThumbTip, new Vector3(0.01f, 1.1f, 0.4f), XRHandJointTrackingState.Pose);
            XRHandsRuntime.Joint(subsystem, Handedness.Right, XRHandJointID.IndexTip, new Vector3(0.03f, 1.1f, 0.4f), high);
            Frames.Run(1);
            Assert.That(source.IsTracked, Is.True);
            Assert.That(Vector3.Distance(source.Position, new Vector3(0.02f, 1.1f, 0.4f)), Is.LessThan(1e-5f), "the tips' midpoint");
            Assert.That(source.IsHighConfidence, Is.False, "the thumb tip is inferred, not tracked with high fidelity");
            XRHandsRuntime.Joint(subsystem, Handedness.Right, XRHandJointID.ThumbTip, new Vector3(0.01f, 1.1f, 0.4f), high);
            Assert.That(source.IsHighConfidence, Is.True);
            subsystem.Destroy();
        }
    }
}
