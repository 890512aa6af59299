using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Meta
{
    /// <summary>
    /// Meta's stock rig for the samples: an <c>OVRCameraRig</c> (TrackingSpace ▸ LeftHandAnchor / RightHandAnchor) with
    /// Meta's <c>OVRHandPrefab</c> (OVRHand, OVRSkeleton, OVRMesh and their renderers) under each hand anchor has no pose
    /// source of this package; the samples' setups (<see cref="SampleContent.HandsInScene"/>) call
    /// <see cref="AddPoseSources"/> to give each <c>OVRHand</c> one. Registered as play mode starts, so the samples (which
    /// Unity compiles without a reference to this assembly) find Meta's hands whenever the Meta XR Core SDK is installed.
    /// </summary>
    public static class OvrRigHands
    {
        [RuntimeInitializeOnLoadMethod(RuntimeInitializeLoadType.SubsystemRegistration)]
        static void Register()
        {
            SampleContent.RegisterOvrHands(AddPoseSources);
            SampleContent.RegisterOvrFloorLevel(UseFloorLevel);
        }

        /// <summary>
        /// The samples' tables stand on y = 0: Meta's stock <c>OVRCameraRig</c> tracks from Eye Level (its prefab's
        /// <c>OVRManager</c> ships <c>_trackingOriginType: 0</c>), where y = 0 is the user's eyes at start and the table would
        /// float 0.75 m above them. Sets the scene's <c>OVRManager</c> to Floor Level when it tracks from Eye Level; true when
        /// it did. Not for per-frame use.
        /// </summary>
        public static bool UseFloorLevel()
        {
            OVRManager manager = OVRManager.instance != null ? OVRManager.instance : Object.FindFirstObjectByType<OVRManager>();
            if (manager == null || manager.trackingOriginType != OVRManager.TrackingOrigin.EyeLevel) return false;
            manager.trackingOriginType = OVRManager.TrackingOrigin.FloorLevel;
            return true;
        }

        /// <summary>
        /// Every enabled <c>OVRHand</c> that no <see cref="OvrHandPoseSource"/> reads gets one on its GameObject, reading
        /// the pinch point (between the thumb and index tips of the prefab's <c>OVRSkeleton</c>, measured from the hand's
        /// own transform: the hand anchor's pose, as the prefab sits at the anchor's origin). Returns how many
        /// <c>OVRHand</c>s there are. Not for per-frame use.
        /// </summary>
        public static int AddPoseSources()
        {
            OVRHand[] hands = Object.FindObjectsByType<OVRHand>(FindObjectsSortMode.InstanceID);
            OvrHandPoseSource[] sources = Object.FindObjectsByType<OvrHandPoseSource>(FindObjectsSortMode.None);
            int count = 0;
            foreach (OVRHand hand in hands)
            {
                if (!hand.enabled) continue;
                count++;
                if (IsRead(hand, sources)) continue;
                OvrHandPoseSource source = hand.gameObject.AddComponent<OvrHandPoseSource>();
                source.InjectHand(hand);
                source.Source = OvrHandPoseSource.PositionSource.PinchPoint; // a pinch grabs there, not at the wrist
            }
            return count;
        }

        static bool IsRead(OVRHand hand, OvrHandPoseSource[] sources)
        {
            foreach (OvrHandPoseSource s in sources)
                if (s.OvrHand == hand || (s.OvrHand == null && s.gameObject == hand.gameObject)) return true;
            return false;
        }
    }
}
