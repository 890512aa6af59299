using Kosmos.PseudoHaptic.Meta;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests.Stock
{
    // Stand-ins for the components Meta's OVRHandPrefab carries beside OVRHand and OVRSkeleton (Meta XR Core SDK 68.0.2:
    // OVRSkeletonRenderer, OVRMesh, OVRMeshRenderer). The package never names them, so the double does not declare them;
    // they are here only so the stock prefab's GameObject holds what Meta's holds. OVRSkeleton is the double's.
    public sealed class OVRSkeletonRenderer : MonoBehaviour { }
    public sealed class OVRMesh : MonoBehaviour { }
    public sealed class OVRMeshRenderer : MonoBehaviour { }

    /// <summary>
    /// Meta's stock rig as its prefabs lay it out: <c>OVRCameraRig</c> (its Awake makes TrackingSpace with LeftHandAnchor,
    /// RightHandAnchor and CenterEyeAnchor) with the prefab's <c>OVRManager</c> beside it (tracking from Eye Level, as
    /// OVRCameraRig.prefab ships it), and, as Meta's hand-tracking set-up says, an <c>OVRHandPrefab</c> (OVRHand,
    /// OVRSkeleton, OVRSkeletonRenderer, OVRMesh, OVRMeshRenderer on one GameObject; its SkinnedMeshRenderer is left out, the double has none) under each hand
    /// anchor; nothing of this package on it.
    /// </summary>
    public static class StockOvrRig
    {
        public static (OVRCameraRig Rig, OVRHand Left, OVRHand Right) Build()
        {
            var rig = new GameObject("OVRCameraRig").AddComponent<OVRCameraRig>();
            rig.gameObject.AddComponent<OVRManager>();
            return (rig, Hand(rig.leftHandAnchor, "OVRHandPrefab"), Hand(rig.rightHandAnchor, "OVRHandPrefab"));
        }

        /// <summary>
        /// The sample scenes' right hand under <paramref name="rig"/>: RightHandAnchor ▸ Hand Visual ▸ OVRHandPrefab (OVRHand,
        /// OVRSkeleton when <paramref name="skeleton"/>, an OVR Hand Pose Source reading the anchor), as the menu builds it.
        /// </summary>
        public static (Transform Visual, OVRHand Hand, OvrHandPoseSource Source) SampleRightHand(OVRCameraRig rig, bool skeleton)
        {
            var visual = new GameObject("Hand Visual").transform;
            visual.SetParent(rig.rightHandAnchor, false);
            var handGo = new GameObject("OVRHandPrefab");
            handGo.transform.SetParent(visual, false);
            OVRHand hand = handGo.AddComponent<OVRHand>();
            if (skeleton) handGo.AddComponent<OVRSkeleton>();
            var source = handGo.AddComponent<OvrHandPoseSource>(); // the default position source
            source.Tracked = rig.rightHandAnchor;
            return (visual, hand, source);
        }

        static OVRHand Hand(Transform anchor, string name)
        {
            var go = new GameObject(name);
            go.transform.SetParent(anchor, false);
            OVRHand hand = go.AddComponent<OVRHand>();
            go.AddComponent<OVRSkeleton>();
            go.AddComponent<OVRSkeletonRenderer>();
            go.AddComponent<OVRMesh>();
            go.AddComponent<OVRMeshRenderer>();
            return hand;
        }
    }
}
