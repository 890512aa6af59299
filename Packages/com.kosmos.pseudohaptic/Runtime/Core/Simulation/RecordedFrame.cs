namespace Kosmos.PseudoHaptic.Simulation
{
    /// <summary>
    /// One frame of a recorded hold: what the solver was given (the hand) and what it answered (the object),
    /// with the configuration it answered under. A row of the recording CSV (<see cref="HoldRecording"/>);
    /// its first four fields are the replay trace format's columns (<see cref="TraceFrame"/>).
    /// </summary>
    public struct RecordedFrame
    {
        /// <summary>Time since the hold began, s (the hold's own clock: the sum of the frame times).</summary>
        public double Time;

        /// <summary>Hand height in the held object's parent space, m; NaN when the hand was not tracked.</summary>
        public double HandY;

        public bool Tracked;

        /// <summary>The tracker reported high confidence (the replay format has no such column: replay takes tracked as confident).</summary>
        public bool HighConfidence;

        /// <summary>When the pose was sampled, s; NaN when unknown.</summary>
        public double PoseTime;

        /// <summary>The object's height in its parent space after this frame, m.</summary>
        public double ObjectY;

        /// <summary>The object's mass, kg (it may change during a hold).</summary>
        public double MassKg;

        /// <summary>The user's standard speed v_std, m/s.</summary>
        public double StandardSpeed;

        /// <summary>The profile's name (<see cref="WeightProfile.Name"/>); the same string instance frame after frame.</summary>
        public string Profile;

        /// <summary>The replay trace's view of this frame: t, hand_y, tracked, pose_t.</summary>
        public TraceFrame ToTraceFrame() => new TraceFrame(Time, HandY, Tracked, PoseTime) { LowConfidence = Tracked && !HighConfidence };
    }
}
