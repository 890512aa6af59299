// Test double of the Meta XR Core SDK 68.0.2's OVRCameraRig (Scripts/OVRCameraRig.cs), the members the package uses.
// As the SDK: Awake makes TrackingSpace and its anchors (LeftHandAnchor, RightHandAnchor, CenterEyeAnchor) under the rig
// if they are missing; Update (and Application.onBeforeRender, the late update) writes the tracked poses into the
// anchors' local poses, in tracking space, then raises UpdatedAnchors. The tracked poses are what the test set
// (UnityDouble.OvrHands.TrackAnchor). Moving the rig (or its tracking space) carries the anchors with it.
using System;
using UnityEngine;

public class OVRCameraRig : MonoBehaviour
{
    public Transform trackingSpace { get; private set; }
    public Transform leftHandAnchor { get; private set; }
    public Transform rightHandAnchor { get; private set; }
    public Transform centerEyeAnchor { get; private set; }

    public event Action<OVRCameraRig> UpdatedAnchors;

    internal Pose LeftHandLocal = Pose.identity, RightHandLocal = Pose.identity, HeadLocal = Pose.identity;

    protected virtual void Awake() => EnsureGameObjectIntegrity();

    protected virtual void Start()
    {
        UpdateAnchors();
        Application.onBeforeRender += UpdateAnchors;
    }

    protected virtual void Update() => UpdateAnchors();

    protected virtual void OnDestroy() => Application.onBeforeRender -= UpdateAnchors;

    void UpdateAnchors()
    {
        EnsureGameObjectIntegrity();
        Set(leftHandAnchor, LeftHandLocal);
        Set(rightHandAnchor, RightHandLocal);
        Set(centerEyeAnchor, HeadLocal);
        UpdatedAnchors?.Invoke(this);
    }

    static void Set(Transform anchor, Pose local)
    {
        anchor.localPosition = local.position;
        anchor.localRotation = local.rotation;
    }

    public virtual void EnsureGameObjectIntegrity()
    {
        if (trackingSpace == null) trackingSpace = Child(transform, "TrackingSpace");
        if (leftHandAnchor == null) leftHandAnchor = Child(trackingSpace, "LeftHandAnchor");
        if (rightHandAnchor == null) rightHandAnchor = Child(trackingSpace, "RightHandAnchor");
        if (centerEyeAnchor == null) centerEyeAnchor = Child(trackingSpace, "CenterEyeAnchor");
    }

    static Transform Child(Transform parent, string name)
    {
        Transform found = parent.Find(name);
        if (found != null) return found;
        var t = new GameObject(name).transform;
        t.SetParent(parent, false);
        return t;
    }
}
