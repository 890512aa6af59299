using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper's named next step (§9, Conclusions): "speed deceleration according to ... the height". An object heavier than the
    /// standard rises more slowly the higher the hand has lifted it, and the more the heavier it is: at lift h (how high
    /// the hand has lifted the object above where the lift began, <see cref="MotionFrame.Lift"/>) the object moves
    /// f(h, m) = φ + (1 − φ) / (1 + w(m) · h / <see cref="Height"/>) as much as it would without the effect, with
    /// φ = <see cref="MinFraction"/> and w(m) = (1 − min(G(m), 1))² the square of the object's weight cue (0 for the standard
    /// weight and anything lighter, rising toward 1 with mass; squared so that the slowing grows clearly with the mass:
    /// 0.34 at 1 kg, 0.46 at 2 kg, 0.71 at 5 kg under `paper`'s gain). So the lift the gain carries is
    /// F(h) = ∫₀ʰ f = φ·h + (1 − φ)·(H/w)·ln(1 + w·h/H): f(0) = 1, f strictly decreasing in h and in m from the first
    /// millimetre, continuous, never below φ, so nothing stalls. Being a function of the lift, a lowering retraces the
    /// rise, and a lift and a lowering end where they began; below the base (lowering past where the lift began) it
    /// changes nothing. One logarithm per frame with a lift. ALGORITHM.md §6 says why this shape.
    /// </summary>
    public sealed class HeightDeceleration : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("height-deceleration", EffectStage.Lift, typeof(HeightDeceleration),
            "§9 (\"the height\")",
            "an object heavier than the standard rises more slowly the higher the hand has lifted it, never below a floor fraction; a lowering retraces it",
            s => new HeightDeceleration(s[0], s[1]),
            SettingDescriptor.Number<HeightDeceleration>("height", "m", 0.125, 0.01, 100, "at this lift a very heavy object moves at the midpoint between full speed and the floor fraction", e => e.Height),
            SettingDescriptor.Number<HeightDeceleration>("minFraction", "", 0.5, 0.01, 1, "the floor fraction: the motion is never multiplied by less", e => e.MinFraction));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
        /// <summary>F is a function of the lift.</summary>
        protected internal override bool IsFunctionOfHand => true;

        /// <summary>Height scale, m: at a lift of this much a very heavy object (w → 1) moves at the midpoint between
        /// full speed and the floor fraction.</summary>
        public double Height { get; }

        /// <summary>The object's motion is never multiplied by less than this (the floor φ), in (0, 1].</summary>
        public double MinFraction { get; }

        public HeightDeceleration(double height = 0.125, double minFraction = 0.5)
        {
            Height = Descriptor.Settings[0].Check(height);
            MinFraction = Descriptor.Settings[1].Check(minFraction);
        }

        /// <summary>w: how strongly an object of gain <paramref name="gain"/> slows with height, (1 − min(G, 1))².</summary>
        public static double Strength(double gain)
        {
            double cue = gain < 1 ? 1 - gain : 0;
            return cue * cue;
        }

        /// <summary>The factor f on the object's motion at lift <paramref name="lift"/> for an object of gain <paramref name="gain"/>.</summary>
        public double Factor(double lift, double gain)
            => MinFraction + (1 - MinFraction) / (1 + Strength(gain) * Math.Max(0, lift) / Height);

        /// <summary>F: the lift the gain carries at lift <paramref name="lift"/> (the integral of <see cref="Factor"/>), m.</summary>
        public double CarriedLift(double lift, double gain)
        {
            double w = Strength(gain);
            if (!(w > 0) || !(lift > 0)) return lift;
            double a = w / Height, x = a * lift, u = 1 + x;
            // ln(1 + x) lost its digits where x is small: 1 + x rounds, and that rounding divided by a reached the lift
            // when a is tiny (a mass just above the standard: 45.00000001 g lagged 10 cm under xyz, 45.000001 g rose 1 cm
            // above the hand). ln(u)·x / (u − 1) is ln(1 + x) to rounding for every x (Goldberg 1991, Theorem 4).
            double ln = u == 1 ? x : Math.Log(u) * x / (u - 1);
            return MinFraction * lift + (1 - MinFraction) * ln / a;
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
            => frame.CarriedLift = CarriedLift(frame.Lift, constants.Gain);
    }
}
