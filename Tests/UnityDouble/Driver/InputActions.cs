using System;
using UnityEngine.InputSystem;

namespace UnityDouble
{
    /// <summary>What the devices behind Input System actions report (the double has no devices): the tests' handle.</summary>
    public static class InputActions
    {
        static readonly InputControl[] OneControl = { new ReportedControl() };

        /// <summary>The action's bound control now reads <paramref name="value"/> (the action has a resolved control from now on).</summary>
        public static void Report<T>(InputAction action, T value) where T : struct
        {
            if (action == null) throw new ArgumentNullException(nameof(action));
            action.m_Reported = value;
            action.m_Controls = OneControl;
        }

        sealed class ReportedControl : InputControl { }
    }
}
