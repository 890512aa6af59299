// Test double of the Meta XR Core SDK 68.0.2's OVRSkeleton and OVRBone (icosa-mirror/com.meta.xr.sdk.core,
// Scripts/Util/OVRSkeleton.cs; enum values from Scripts/OVRPlugin.cs: OVRPlugin.SkeletonType, OVRPlugin.BoneId),
// global namespace, assembly Oculus.VR. As the SDK: Bones is an empty read-only list from Awake (null before) and
// IsInitialized is false until the runtime gives the skeleton (OVRSkeleton.Initialize, from Start or Update); the
// bones' transforms then sit under a "Bones" child of the skeleton's transform; a re-initialization after the
// runtime's skeleton changed counts SkeletonChangedCount up and keeps the bone transforms, unless the bone count
// changed (then the old bones are disposed, their GameObjects destroyed, and Bones is a new list). Here the runtime is
// the test (UnityDouble.OvrHands.InitializeSkeleton / PoseSkeleton), and the double's bones hang flat under "Bones"
// (the SDK parents them by the runtime's parent indices) with only the two fingertips placed.
using System;
using System.Collections.Generic;
using UnityEngine;

public class OVRSkeleton : MonoBehaviour
{
    public enum SkeletonType
    {
        None = -1,
        HandLeft = 0,
        HandRight = 1,
        Body = 2,
    }

    public enum BoneId
    {
        // OVRPlugin.BoneId: Hand_MaxSkinnable (19) + 0 and + 1; a hand skeleton has the ids 0 to Hand_End - 1 (23).
        Hand_ThumbTip = 19,
        Hand_IndexTip = 20,
    }

    internal const int HandBoneCount = 24; // OVRPlugin.BoneId.Hand_End

    [SerializeField] protected SkeletonType _skeletonType = SkeletonType.None;

    List<OVRBone> _bones;
    GameObject _bonesGO;

    public bool IsInitialized { get; private set; }
    public IList<OVRBone> Bones { get; protected set; }
    public int SkeletonChangedCount { get; private set; }

    public SkeletonType GetSkeletonType() => _skeletonType;

    protected virtual void Awake()
    {
        _bones = new List<OVRBone>();
        Bones = _bones.AsReadOnly();
    }

    /// <summary>
    /// The double's own: the runtime gives the skeleton of <paramref name="type"/> with <paramref name="boneCount"/>
    /// bones (a hand's 24 by default), as OVRSkeleton.Initialize builds it; again on an initialized skeleton, as after
    /// the runtime's skeleton changed.
    /// </summary>
    internal void InitializeFromRuntime(SkeletonType type, int boneCount)
    {
        if (IsInitialized) SkeletonChangedCount++;
        _skeletonType = type;
        if (_bonesGO == null)
        {
            _bonesGO = new GameObject("Bones");
            _bonesGO.transform.SetParent(transform, false);
        }
        if (_bones.Count != boneCount)
        {
            foreach (OVRBone old in _bones) old.Dispose();
            _bones = new List<OVRBone>(boneCount);
            Bones = _bones.AsReadOnly();
        }
        for (int i = 0; i < boneCount; i++)
        {
            if (i == _bones.Count) _bones.Add(new OVRBone());
            OVRBone bone = _bones[i];
            bone.Id = (BoneId)i;
            if (bone.Transform == null)
            {
                bone.Transform = new GameObject("Bone " + i).transform;
                bone.Transform.SetParent(_bonesGO.transform, false);
            }
        }
        IsInitialized = true;
    }
}

public class OVRBone : IDisposable
{
    public OVRSkeleton.BoneId Id { get; set; }
    public Transform Transform { get; set; }

    public OVRBone()
    {
    }

    public void Dispose()
    {
        if (Transform != null)
        {
            UnityEngine.Object.Destroy(Transform.gameObject);
            Transform = null;
        }
    }
}
