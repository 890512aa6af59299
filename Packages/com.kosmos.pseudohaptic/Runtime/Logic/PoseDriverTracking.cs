namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Whether a hand posed by the Input System's <c>TrackedPoseDriver</c> has a tracked position now, engine-free: what the
    /// XR Interaction Toolkit 3.x grab transformer asks of the driver that moves an interactor (XRI 3 dropped the
    /// controller components and poses controllers and hands with that driver). It is the driver's own rule for moving its
    /// transform (Input System 1.8.1, <c>TrackedPoseDriver.ReadTrackingState</c> and <c>SetLocalTransform</c>), read through
    /// its public members: no driver, a driver told to ignore the tracking state, or no tracking-state action: tracked (the
    /// driver always moves the transform); a disabled action: not tracked (the driver reads it as None); an action whose
    /// bindings found no control: tracked (the driver keeps its state, Position | Rotation until a control reports one);
    /// otherwise the action's value has <see cref="Position"/>. When it is false the driver leaves the transform where it
    /// was, so the hand is lost, not still.
    /// </summary>
    public static class PoseDriverTracking
    {
        /// <summary><c>UnityEngine.XR.InputTrackingState.Position</c>, the bit of the tracking-state action's int value.</summary>
        public const int Position = 1;

        public static bool PositionTracked(bool hasDriver, bool ignoreTrackingState, bool hasAction, bool actionEnabled, int resolvedControls, int trackingState)
        {
            if (!hasDriver || ignoreTrackingState || !hasAction) return true;
            if (!actionEnabled) return false;
            if (resolvedControls <= 0) return true;
            return (trackingState & Position) != 0;
        }
    }
}
