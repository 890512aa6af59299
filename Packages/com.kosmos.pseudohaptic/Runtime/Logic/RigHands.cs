namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// What a sample's setup says about the hands it found in the scene, engine-free: nothing when it found a hand to
    /// grab with, else one warning naming what is missing. A setup looks for the package's pinch pose sources
    /// (OvrHandPoseSource, XRHandPoseSource, TransformHandPoseSource, any IPinchHandPoseSource) after giving each of
    /// Meta's <c>OVRHand</c>s one (when the Meta XR Core SDK is installed), so the stock <c>OVRCameraRig</c> with an
    /// <c>OVRHandPrefab</c> under each hand anchor needs nothing more.
    /// </summary>
    public static class RigHands
    {
        /// <summary>
        /// The warning for <paramref name="sample"/>, or null when <paramref name="pinchSources"/> &gt; 0.
        /// <paramref name="ovrLookedFor"/>: the Meta XR Core SDK's hands were looked for (its assembly is loaded);
        /// <paramref name="ovrHands"/>: how many enabled <c>OVRHand</c>s were found.
        /// </summary>
        public static string MissingHandsWarning(string sample, int pinchSources, bool ovrLookedFor, int ovrHands)
        {
            if (pinchSources > 0) return null;
            string who = string.IsNullOrEmpty(sample) ? "Kosmos Pseudo-Haptic sample" : sample;
            string rig = !ovrLookedFor
                ? "the Meta XR Core SDK (com.meta.xr.sdk.core) is not installed, so no OVRHand was looked for"
                : ovrHands == 0
                    ? "the scene has no enabled OVRHand (Meta's stock rig: an OVRCameraRig with an OVRHandPrefab under TrackingSpace/LeftHandAnchor and TrackingSpace/RightHandAnchor)"
                    : "its OVRHands could not be given a pose source";
            return who + ": no hand to grab with, so nothing can be grabbed or poked: " + rig
                   + ", and no other pinch pose source is enabled (XR Hands Pose Source, Transform Hand Pose Source, or any IPinchHandPoseSource).";
        }
    }
}
