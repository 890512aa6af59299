using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// A glitch of two or three poses down while the hand rests at the lift's base (at the grab, or after lowering the
    /// object). The median of three passes such a glitch into the steady hand, and the lowering guard
    /// (<see cref="LoweringGuard"/>) followed it down, until it undid a drop the hand came back up from within five steady
    /// poses: the base stayed 1–4 cm low for the rest of the hold, and the object with it, by (G − 1) × the drop (a 1 g
    /// object, G = 3, floated 47 mm above the hand after a 3 cm glitch; a heavy one sank). P12 (one source of offset): the
    /// same path clean and with the glitch ends in the same place.
    /// </summary>
    public class TwoPoseGlitchTests
    {
        static readonly double[] Masses = { 0.001, 0.01, PhysicalConstants.StandardMassKg, 0.5, 2 };

        /// <summary>
        /// Over 200 seeds for each pipeline profile: the hand rests 0.3–1 s at the grab, or lowers the object 5–20 cm in
        /// 0.5–1 s and rests 0.5–1 s; then 2 or 3 consecutive poses are 1–4 cm low (on Quest-like input: 1–2 mm of jitter,
        /// 45 ms late, its own one-pose glitches and low-confidence poses); then 2 s at rest. The object's median over the
        /// last second is where the same run without the glitch puts it: within 1 mm for the standard weight, 1 cm for a
        /// heavier or lighter one (P12's bounds). Measured at most 4.40 mm at 1 g, 2.61 mm at 10 g, 0.00 mm at 0.5 and 2 kg
        /// (under <c>gain</c>, which has no lowering guard, 5.55 and 8.13 mm at 1 g and 10 g: the deadband's); with the base
        /// following the steady hand at once, 71.71 mm at 1 g, 61.23 mm at 10 g, 17.48–23.03 mm at 0.5–2 kg.
        /// </summary>
        [Test]
        public void AGlitchOfTwoOrThreePosesDownAtTheBaseLeavesNothing([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            double worst = 0;
            string worstCase = "";
            var worstByMass = new double[Masses.Length];
            var profileNamed = NamedProfiles.Get(profile);
            for (int seed = 1; seed <= 200; seed++)
            {
                var rng = new Random(seed);
                double mass = Masses[seed % Masses.Length];
                bool lowered = rng.NextDouble() < 0.5;
                var path = HandPath.StartAt(1.2);
                if (lowered) path.Hold(0.3).MoveTo(1.2 - QuestLikeInput.Uniform(rng, 0.05, 0.2), QuestLikeInput.Uniform(rng, 0.5, 1));
                path.Hold(QuestLikeInput.Uniform(rng, lowered ? 0.5 : 0.3, 1));
                int poses = 2 + rng.Next(2);
                double size = QuestLikeInput.Uniform(rng, 0.01, 0.04);
                // From between two poses, so that exactly `poses` poses are off (the headset's poses are 1/30 s apart).
                double at = (Math.Floor(path.Duration * 30) + 0.5) / 30;
                path.Hold(2);
                var clean = QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(path);
                var glitched = QuestLikeInput.Headset(new Random(seed * 7919), seed).Offset(at, poses / 30.0, -size).Render(path);
                var a = Run.Replay(Run.Solver(mass, profileNamed), clean);
                var b = Run.Replay(Run.Solver(mass, profileNamed), glitched);
                Assert.That(Run.AllFinite(b), Is.True);
                double end = path.Duration;
                double d = QuestLikeInput.MedianOver(glitched, i => b[i], end - 1, end + 1) - QuestLikeInput.MedianOver(clean, i => a[i], end - 1, end + 1);
                double bound = mass == PhysicalConstants.StandardMassKg ? 0.001 : 0.01;
                worstByMass[seed % Masses.Length] = Math.Max(worstByMass[seed % Masses.Length], Math.Abs(d));
                if (Math.Abs(d) / bound > Math.Abs(worst))
                {
                    worst = d / bound;
                    worstCase = $"seed {seed}: {mass * 1000} g, {(lowered ? "after lowering" : "at the grab")}, {poses} poses {size * 1000:F1} mm down: ends {d * 1000:F2} mm from the clean run";
                }
            }
            var byMass = new System.Text.StringBuilder();
            for (int m = 0; m < Masses.Length; m++) byMass.Append($"{(m > 0 ? ", " : "")}{Masses[m] * 1000} g {worstByMass[m] * 1000:F2} mm");
            TestContext.Progress.WriteLine($"{profile}: after a glitch of two or three poses down at the base the object ends at most {byMass} from the clean run; worst {Math.Abs(worst) * 100:F0} % of P12's bound ({worstCase})");
            Assert.That(Math.Abs(worst), Is.LessThanOrEqualTo(1), worstCase);
        }
    }
}
