using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>One generated hard case: the frames a headset would deliver, the object and the user.</summary>
    internal sealed class Scenario
    {
        public int Seed;
        public string Description;
        public HandPath Path;
        public TraceFrame[] Frames;
        public double MassKg;
        public double StandardSpeed;
        public string Profile;

        /// <summary>True when the frames carry only realistic degradation (no dropouts, glitches or garbage).</summary>
        public bool IsClean;

        public override string ToString() => "seed " + Seed + ": " + Description;
    }
}
