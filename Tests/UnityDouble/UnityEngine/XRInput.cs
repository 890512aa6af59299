// Test double of UnityEngine.XR.InputTrackingState (Unity 2022.3, UnityCsReference Modules/XR/ScriptBindings/XRInput.bindings.cs,
// module UnityEngine.XRModule): the flags XR Interaction Toolkit's controller state reports.
using System;

namespace UnityEngine.XR
{
    [Flags]
    public enum InputTrackingState : uint
    {
        None = 0,
        Position = 1 << 0,
        Rotation = 1 << 1,
        Velocity = 1 << 2,
        AngularVelocity = 1 << 3,
        Acceleration = 1 << 4,
        AngularAcceleration = 1 << 5,
        All = (1 << 6) - 1,
    }
}
