// Test double of XR Core Utilities' XROrigin (com.unity.xr.core-utils 2.x, Runtime/XROrigin.cs, assembly
// Unity.XR.CoreUtils, which com.unity.xr.hands 1.5.0 depends on): the members the package uses, as plain properties.
using UnityEngine;

namespace Unity.XR.CoreUtils
{
    public class XROrigin : MonoBehaviour
    {
        /// <summary>The origin's base GameObject (this one by default).</summary>
        public GameObject Origin { get; set; }

        /// <summary>The GameObject moved to the camera's height off the floor: tracked poses are in its space.</summary>
        public GameObject CameraFloorOffsetObject { get; set; }

        public Camera Camera { get; set; }
    }
}
