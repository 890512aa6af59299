// Test double of the Input System 1.8.1 (com.unity.inputsystem, assembly Unity.InputSystem; XR Interaction Toolkit 3.0.8
// asks for 1.8.1), as mirrored in needle-mirror/com.unity.inputsystem at tag 1.8.1: InputSystem/Actions/InputAction.cs,
// InputActionProperty.cs, InputActionType.cs, InputSystem/Controls/InputControl.cs, InputSystem/Utilities/ReadOnlyArray.cs,
// InputSystem/Plugins/XR/TrackedPoseDriver.cs. Declarations transcribed (namespaces, names, types; only the members the
// package calls and the tests need); bodies written here after those sources (no code copied):
// - InputAction: no devices here. An action's value is what the test reports (Driver: UnityDouble.InputActions.Report);
//   once reported, the action has one resolved control (`controls`), as a binding that found its device; before that,
//   none. `enabled` follows Enable/Disable. ReadValue<T> returns the reported value, or default(T) when it is not a T
//   (as the real one reads a control's value, or default without one).
// - TrackedPoseDriver: enables and disables the actions defined in its properties (not references) in OnEnable and
//   OnDisable; before every script's Update (the real one updates in InputSystem.onAfterUpdate, which the player loop
//   runs before scripts) and before rendering (UpdateType.UpdateAndBeforeRender, its default) it reads position,
//   rotation and tracking state and writes its local pose, position only when the tracking state has Position, rotation
//   only when it has Rotation (SetLocalTransform), both always with ignoreTrackingState. The tracking state, as its
//   ReadTrackingState: no action, or an action with no resolved control, keeps the last state (Position | Rotation
//   at start); a disabled action is None; otherwise the action's int value.
using System;
using System.Collections;
using System.Collections.Generic;
using UnityEngine.InputSystem.Utilities;

namespace UnityEngine.InputSystem
{
    public enum InputActionType
    {
        Value,
        Button,
        PassThrough,
    }

    public abstract class InputControl
    {
    }

    public sealed class InputAction
    {
        readonly string m_Name;
        internal object m_Reported;
        internal InputControl[] m_Controls = Array.Empty<InputControl>();
        bool m_Enabled;

        public InputAction(string name = null, InputActionType type = default, string binding = null,
                           string interactions = null, string processors = null, string expectedControlType = null)
        {
            m_Name = name;
        }

        public string name => m_Name;
        public bool enabled => m_Enabled;
        public ReadOnlyArray<InputControl> controls => new ReadOnlyArray<InputControl>(m_Controls);

        public void Enable() => m_Enabled = true;
        public void Disable() => m_Enabled = false;

        public TValue ReadValue<TValue>() where TValue : struct => m_Reported is TValue value ? value : default;
    }

    public struct InputActionProperty
    {
        readonly InputAction m_Action;

        public InputActionProperty(InputAction action) => m_Action = action;

        public InputAction action => m_Action;
    }
}

namespace UnityEngine.InputSystem.Utilities
{
    public struct ReadOnlyArray<TValue> : IReadOnlyList<TValue>
    {
        readonly TValue[] m_Array;

        public ReadOnlyArray(TValue[] array) => m_Array = array;

        public int Count => m_Array != null ? m_Array.Length : 0;
        public TValue this[int index] => m_Array[index];

        public IEnumerator<TValue> GetEnumerator() => ((IEnumerable<TValue>)(m_Array ?? Array.Empty<TValue>())).GetEnumerator();
        IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
    }
}

namespace UnityEngine.InputSystem.XR
{
    [DefaultExecutionOrder(-30000)] // stands for InputSystem.onAfterUpdate, which runs before every script's Update
    [AddComponentMenu("XR/Tracked Pose Driver (Input System)")]
    public class TrackedPoseDriver : MonoBehaviour
    {
        [Flags]
        enum TrackingStates
        {
            None = 0,
            Position = 1 << 0,
            Rotation = 1 << 1,
        }

        [SerializeField] bool m_IgnoreTrackingState;
        [SerializeField] InputActionProperty m_PositionInput, m_RotationInput, m_TrackingStateInput;
        TrackingStates m_CurrentTrackingState = TrackingStates.Position | TrackingStates.Rotation;
        Vector3 m_CurrentPosition = Vector3.zero;
        Quaternion m_CurrentRotation = Quaternion.identity;

        public bool ignoreTrackingState { get => m_IgnoreTrackingState; set => m_IgnoreTrackingState = value; }

        public InputActionProperty positionInput { get => m_PositionInput; set => Swap(ref m_PositionInput, value); }
        public InputActionProperty rotationInput { get => m_RotationInput; set => Swap(ref m_RotationInput, value); }
        public InputActionProperty trackingStateInput { get => m_TrackingStateInput; set => Swap(ref m_TrackingStateInput, value); }

        void Swap(ref InputActionProperty property, InputActionProperty value)
        {
            if (isActiveAndEnabled) property.action?.Disable();
            property = value;
            if (isActiveAndEnabled) property.action?.Enable();
        }

        protected void OnEnable()
        {
            m_PositionInput.action?.Enable();
            m_RotationInput.action?.Enable();
            m_TrackingStateInput.action?.Enable();
            Application.onBeforeRender += PerformUpdate;
        }

        protected void OnDisable()
        {
            Application.onBeforeRender -= PerformUpdate;
            m_PositionInput.action?.Disable();
            m_RotationInput.action?.Disable();
            m_TrackingStateInput.action?.Disable();
        }

        void Update() => PerformUpdate();

        void PerformUpdate()
        {
            InputAction state = m_TrackingStateInput.action;
            if (state != null && !state.enabled) m_CurrentTrackingState = TrackingStates.None;
            else if (state != null && state.controls.Count > 0) m_CurrentTrackingState = (TrackingStates)state.ReadValue<int>();
            // The real one keeps the last value each action performed with (its callbacks); here: the last value reported.
            if (m_PositionInput.action != null && m_PositionInput.action.controls.Count > 0) m_CurrentPosition = m_PositionInput.action.ReadValue<Vector3>();
            if (m_RotationInput.action != null && m_RotationInput.action.controls.Count > 0) m_CurrentRotation = m_RotationInput.action.ReadValue<Quaternion>();
            bool position = m_IgnoreTrackingState || (m_CurrentTrackingState & TrackingStates.Position) != 0;
            bool rotation = m_IgnoreTrackingState || (m_CurrentTrackingState & TrackingStates.Rotation) != 0;
            if (rotation) transform.localRotation = m_CurrentRotation;
            if (position) transform.localPosition = m_CurrentPosition;
        }
    }
}
