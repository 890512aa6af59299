namespace Kosmos.PseudoHaptic
{
    /// <summary>A hand source that reports how far the index pinch is closed, 0 … 1 (OVRHand, Unity XR Hands).</summary>
    public interface IPinchStrengthSource
    {
        float PinchStrength { get; }
    }

    /// <summary>The pinch strength of any pinch source: its own when it reports one, else 1 or 0 from its pinch flag.</summary>
    public static class PinchSources
    {
        public static double Strength(IPinchHandPoseSource hand) =>
            hand is IPinchStrengthSource s ? s.PinchStrength : hand != null && hand.IsPinching ? 1 : 0;
    }
}
