namespace Kosmos.PseudoHaptic.Simulation
{
    /// <summary>One rendered frame of a hand trace: the columns of the replay file format.</summary>
    public struct TraceFrame
    {
        /// <summary>Frame time, s.</summary>
        public double Time;

        /// <summary>Tracked hand height, m (NaN or infinite when garbage).</summary>
        public double HandY;

        public bool Tracked;

        /// <summary>When the pose was sampled, s; NaN when unknown.</summary>
        public double PoseTime;

        /// <summary>Tracked, but the tracker reported low confidence (Quest does in fast motion). The replay format has
        /// no such column: a replayed row is confident when tracked.</summary>
        public bool LowConfidence;

        public TraceFrame(double time, double handY, bool tracked = true, double poseTime = double.NaN)
        {
            Time = time;
            HandY = handY;
            Tracked = tracked;
            PoseTime = poseTime;
            LowConfidence = false;
        }

        /// <summary>The frame has a pose the solver can follow (<see cref="HandSample.IsUsable"/>).</summary>
        public bool IsUsable => Tracked && HandSample.IsUsableHeight(HandY);

        public HandSample ToSample() => new HandSample(HandY, Tracked, Tracked && !LowConfidence, PoseTime);
    }
}
