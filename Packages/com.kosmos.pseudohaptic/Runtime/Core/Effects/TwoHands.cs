namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A hold in <see cref="WeightSolver3D"/> may have a second hand. The object follows the followed hands'
    /// midpoint, and while both hands hold, each carries <see cref="Share"/> of the mass (but never less than the
    /// standard weight, or the whole mass when it is lighter): every effect sees the per-hand mass, so a two-hand lift
    /// of m moves as a one-hand lift of max(m·share, min(m, 45 g)) at the midpoint. When one
    /// hand is lost or lets go the hold goes on with the other, the followed point re-anchored so nothing
    /// steps; a returning hand rejoins after the profile's tracking-loss settle time.
    /// Without this effect the second hand is ignored.
    /// </summary>
    public sealed class TwoHands : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("two-hands", EffectStage.Hold, typeof(TwoHands),
            "the paper's participants lifted with both hands",
            "in WeightSolver3D, a second hand: the object follows the midpoint and each hand carries a share of the mass",
            s => new TwoHands(s[0]),
            SettingDescriptor.Number<TwoHands>("share", "", 0.5, 0.001, 1, "the share of the mass each hand carries while both hold", e => e.Share));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        /// <summary>The share of the mass each hand carries while both hold, (0, 1].</summary>
        public double Share { get; }

        public TwoHands(double share = 0.5)
        {
            Share = Descriptor.Settings[0].Check(share);
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
