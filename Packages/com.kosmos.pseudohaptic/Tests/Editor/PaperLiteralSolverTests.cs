using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// <see cref="PaperLiteralSolver"/>, the paper as printed (ALGORITHM.md §12), against hand computations: Eq. 1, 2, 4, 5
    /// and 6 in their relative reading with the paper's own constants (g = 9.80665 m/s², the golf ball's 0.045 kg, Eq. 5's
    /// 1.6793 m/s and 0.24 /kg, written here, not taken from the solver), the hand's speed averaged over the unit time of
    /// 1 s (the average speed over the last second of the hand's path, straight between frames, the hand resting where it
    /// was grabbed before the grab: the object then moves G times the change of the hand's mean height over the last
    /// second, which these tests compute by hand), the gain cap of 3 (P3), and what it must absorb: a bad frame time, an
    /// untracked frame, a hold begun before the hand was seen, a hold begun after another one, any frame times. Frames are
    /// 1/8 s long so that the clock is exact and the last second is exactly 8 frames.
    /// </summary>
    public class PaperLiteralSolverTests
    {
        const double G = 9.80665, GolfBallKg = 0.045, CurveA = 1.6793, CurveB = 0.24;
        const double Dt = 0.125;
        const double Exact = 1e-12;

        /// <summary>algorithm-reading.md's P3: the gain cap that holds in every profile.</summary>
        const double Cap = 3;

        /// <summary>The gain at cue strength <paramref name="s"/> as every profile has it (P3, ALGORITHM.md §12): G capped,
        /// then G^s capped (1 g, G ≈ 23, at s = 1/3: 3^(1/3), not 23^(1/3)).</summary>
        static double CappedGain(double massKg, double s) => Math.Min(Math.Pow(Math.Min(PaperGain(massKg), Cap), s), Cap);

        /// <summary>Eq. 6 in its relative reading, as a gain on the mean hand speed: ½(W_std/W + v_exp(m)/v_exp(m_std)),
        /// W = m·g (Eq. 1), W_std = 0.045 kg·g (Eq. 2), v_exp(m) = 1.6793·e^(−0.24·m) (Eq. 5).</summary>
        static double PaperGain(double massKg)
        {
            double weight = massKg * G, standardWeight = GolfBallKg * G;
            double vExp = CurveA * Math.Exp(-CurveB * massKg), vExpStandard = CurveA * Math.Exp(-CurveB * GolfBallKg);
            return (standardWeight / weight + vExp / vExpStandard) / 2;
        }

        [Test]
        public void TheHandComputedGainIsTheDesignNotes()
        {
            // algorithm-reading.md's sample gains: this test's own Eq. 6 is the paper's, not a copy of the solver's.
            Assert.That(PaperGain(GolfBallKg), Is.EqualTo(1).Within(Exact), "the golf ball moves with the hand");
            Assert.That(PaperGain(0.1), Is.EqualTo(0.72).Within(0.005));
            Assert.That(PaperGain(1), Is.EqualTo(0.42).Within(0.005));
            Assert.That(PaperGain(2), Is.EqualTo(0.32).Within(0.005));
            Assert.That(PaperGain(0.01), Is.EqualTo(2.75).Within(0.005));
        }

        /// <summary>At the cue strength 1 each frame is Eq. 6 as printed, bit for bit: v_final = (v_virtual + v_real ·
        /// v_exp(m)/v_exp(m_std)) / 2 with v_virtual = v_real · W_std / W (Eq. 4), not the algebraically equal gain form
        /// v_real · ½(W_std/W + v_exp(m)/v_exp(m_std)) the other cue strengths use, which rounds differently: a researcher
        /// replaying the paper's equations gets them as written. One frame of 0.5 s in which the hand rises 0.375 m from rest:
        /// its mean height over the last second rises by the ramp's half over half the window, 0.09375 m (exact in binary),
        /// so v_real = 0.1875 m/s; 200 masses from 15 g to 20 kg (below the cap: above it the cap's form is used).</summary>
        [Test]
        public void AtCueStrengthOneEachFrameIsEquationSixAsPrintedBitForBit()
        {
            var rng = new Random(6);
            int differs = 0;
            const double dt = 0.5, vReal = 0.1875;
            for (int i = 0; i < 200; i++)
            {
                double massKg = 0.015 * Math.Pow(20 / 0.015, rng.NextDouble());
                var solver = new PaperLiteralSolver(massKg);
                solver.BeginHold(1.0, 1.0);
                double weight = massKg * G, standardWeight = GolfBallKg * G;
                double vVirtual = vReal * standardWeight / weight;
                double vExp = CurveA * Math.Exp(-CurveB * massKg), vExpStandard = CurveA * Math.Exp(-CurveB * GolfBallKg);
                double printed = 1.0 + (vVirtual + vReal * vExp / vExpStandard) / 2 * dt;
                double gainForm = 1.0 + vReal * ((standardWeight / weight + vExp / vExpStandard) / 2) * dt;
                if (printed != gainForm) differs++;
                Assert.That(solver.Step(1.375, true, dt), Is.EqualTo(printed), $"{massKg} kg");
            }
            Assert.That(differs, Is.GreaterThan(0), "the two forms round apart for some masses, so the test can tell them");
        }

        /// <summary>
        /// The hand rests for a second, rises 8 cm in one frame (1/8 s) and rests again. Its mean height over the last second
        /// rises by 5 mm over that frame (the ramp's half, over an eighth of the window), by 1 cm over each of the next seven
        /// and by 5 mm over the one after, so the object climbs G^s (capped at 3) times that and then stands still, G^s · 8 cm
        /// above where it was.
        /// </summary>
        [Test]
        public void AOneFrameMoveIsSpreadOverTheNextSecond([Values(0.01, 0.045, 0.5, 2, 5)] double massKg, [Values(1.0, 0.5, 2.0)] double strength)
        {
            var solver = new PaperLiteralSolver(massKg) { CueStrength = strength };
            solver.BeginHold(1.0, 1.0);
            double gain = CappedGain(massKg, strength), step = 0.08;
            for (int frame = 1; frame <= 32; frame++)
            {
                double hand = frame < 9 ? 1.0 : 1.0 + step;
                double y = solver.Step(hand, true, Dt);
                double meanRise = frame < 9 ? 0 : frame >= 17 ? step : 0.005 + 0.01 * (frame - 9);
                Assert.That(y, Is.EqualTo(1.0 + gain * meanRise).Within(Exact), $"frame {frame} (t = {frame * Dt} s)");
            }
            Assert.That(solver.ObjectY - 1.0, Is.EqualTo(gain * step).Within(Exact), "the object ends G^s times the hand's move above");
        }

        /// <summary>
        /// "The unit time for measuring the average speed is 1 s": a hand lifting at 0.4 m/s from the grab for 2 s. The object
        /// was at rest before the grab, so the mean speed over the last second grows over the first second (the mean height
        /// 0.5 + 0.2 t²), is the hand's 0.4 m/s while the window holds only the lift (0.5 + 0.4 (t − ½)), falls off over the
        /// second after the stop (1.3 − 0.2 (3 − t)²) and is 0 from then on: the object moves G times the mean height's change
        /// and stands still G · 0.8 m above where it was a second after the hand.
        /// </summary>
        [Test]
        public void ASteadyLiftMovesAtTheGainOnceTheSecondHoldsOnlyTheLiftAndStopsOneSecondAfterTheHand()
        {
            var solver = new PaperLiteralSolver(1);
            solver.BeginHold(0.5, 0.5);
            double gain = PaperGain(1), hand = 0.5;
            for (int frame = 1; frame <= 40; frame++)
            {
                if (frame <= 16) hand = 0.5 + 0.4 * Dt * frame; // 2 s at 0.4 m/s, then still
                double t = frame * Dt;
                double mean = t <= 1 ? 0.5 + 0.2 * t * t : t <= 2 ? 0.5 + 0.4 * (t - 0.5) : t <= 3 ? 1.3 - 0.2 * (3 - t) * (3 - t) : 1.3;
                Assert.That(solver.Step(hand, true, Dt), Is.EqualTo(0.5 + gain * (mean - 0.5)).Within(Exact), $"frame {frame} (t = {t} s)");
            }
            Assert.That(solver.ObjectY, Is.EqualTo(0.5 + gain * 0.8).Within(Exact));
        }

        /// <summary>
        /// P1 for the paper as printed: the golf ball (G = 1) ends at the hand, and every mass G^s (capped) times the hand's
        /// lift from the grab, whatever the frames (300 seeds: 30–120 Hz with jitter, a 0.1 s hitch, a lift of 5–60 cm in
        /// 0.2–1.5 s starting at the grab, then 1.2 s of rest). The mean of the frame speeds of the last second, taken over the
        /// frames the hold had so far (the reading before this one), left the golf ball up to 18 cm above the hand after a
        /// lift begun at the grab, and a hitch moved it off by centimetres.
        /// </summary>
        [Test]
        public void TheObjectEndsGTimesTheHandsLiftWhateverTheFrames()
        {
            double[] masses = { 0.001, 0.01, GolfBallKg, 0.3, 1, 2.7, 8 };
            for (int seed = 0; seed < 300; seed++)
            {
                var rng = new Random(seed);
                double massKg = masses[seed % masses.Length], strength = seed % 3 == 0 ? 1 : 1.0 / 3 + rng.NextDouble() * (3 - 1.0 / 3);
                double rate = 30 + rng.NextDouble() * 90, lift = 0.05 + rng.NextDouble() * 0.55, duration = 0.2 + rng.NextDouble() * 1.3;
                double hitchAt = rng.NextDouble() * (duration + 1.0);
                var solver = new PaperLiteralSolver(massKg) { CueStrength = strength };
                double start = 0.8, t = 0;
                solver.BeginHold(start, start);
                bool hitched = false;
                while (t < duration + 1.2)
                {
                    double dt = (1 / rate) * (0.7 + 0.6 * rng.NextDouble());
                    if (!hitched && t >= hitchAt) { dt = 0.1; hitched = true; }
                    t += dt;
                    double u = Math.Min(t / duration, 1);
                    solver.Step(start + lift * u * u * u * (10 + u * (-15 + 6 * u)), true, dt);
                }
                double expected = start + CappedGain(massKg, strength) * lift;
                Assert.That(solver.ObjectY, Is.EqualTo(expected).Within(1e-9), $"seed {seed}: {massKg} kg, s {strength:0.###}, {rate:0} Hz, {lift:0.###} m in {duration:0.##} s");
            }
        }

        [Test]
        public void ANewHoldForgetsTheLast()
        {
            // A fresh solver and one that has just held a rising object (a lift still going at 32 Hz) run the same
            // second hold at 8 Hz: rest, a 0.2 m lift in 0.5 s, rest. Nothing of the first hold may show, bit for bit.
            var used = new PaperLiteralSolver(2);
            used.BeginHold(1.0, 1.0);
            for (int frame = 1; frame <= 42; frame++) used.Step(1.0 + frame * 0.5 / 32, true, 1.0 / 32);
            var fresh = new PaperLiteralSolver(2);
            used.BeginHold(0.4, 0.3);
            fresh.BeginHold(0.4, 0.3);
            for (int frame = 1; frame <= 24; frame++)
            {
                double hand = frame <= 4 ? 0.4 : frame <= 8 ? 0.4 + 0.05 * (frame - 4) : 0.6;
                double expected = fresh.Step(hand, true, Dt);
                Assert.That(used.Step(hand, true, Dt), Is.EqualTo(expected), $"frame {frame}");
                if (frame <= 4) Assert.That(expected, Is.EqualTo(0.3), "a still hand leaves the object still");
            }
        }

        /// <summary>A frame time that is not positive or not finite is no frame: the step returns the object where it was
        /// and leaves no trace (the hand height it came with is not taken), so the path is the clean one, bit for bit.</summary>
        [Test]
        public void ABadFrameTimeIsAbsorbedWithoutATrace([Values(0.0, -0.125, double.NaN, double.PositiveInfinity, double.NegativeInfinity)] double badDt)
        {
            var clean = new PaperLiteralSolver(2);
            var glitched = new PaperLiteralSolver(2);
            clean.BeginHold(1.0, 1.0);
            glitched.BeginHold(1.0, 1.0);
            for (int frame = 1; frame <= 30; frame++)
            {
                double hand = 1.0 + 0.3 * Math.Sin(frame * 0.3);
                if (frame % 3 == 0)
                {
                    double before = glitched.ObjectY;
                    Assert.That(glitched.Step(hand + 0.5, true, badDt), Is.EqualTo(before), $"frame {frame}: dt = {badDt}");
                    Assert.That(glitched.Step(hand - 0.5, false, badDt), Is.EqualTo(before));
                }
                double expected = clean.Step(hand, true, Dt);
                Assert.That(glitched.Step(hand, true, Dt), Is.EqualTo(expected), $"frame {frame} after dt = {badDt}");
            }
            Assert.That(clean.ObjectY, Is.Not.EqualTo(1.0), "the hand moved the object");
        }

        /// <summary>A frame without a usable hand (untracked, even with a plausible height; tracked with a NaN or a
        /// height beyond ±10⁵ m) is a still frame: the object does not move, and the next tracked height is reached from
        /// the last tracked one over the frame it comes in, so the move is spread over the next second as any other.</summary>
        [TestCase(false, 1.7)]
        [TestCase(true, double.NaN)]
        [TestCase(true, 2e5)]
        public void AFrameWithoutAUsableHandCountsAsAStillOne(bool tracked, double reported)
        {
            var solver = new PaperLiteralSolver(2);
            solver.BeginHold(1.0, 1.0);
            double gain = PaperGain(2);
            for (int frame = 1; frame <= 8; frame++) Assert.That(solver.Step(1.0, true, Dt), Is.EqualTo(1.0));
            Assert.That(solver.Step(reported, tracked, Dt), Is.EqualTo(1.0), "frame 9: no usable hand, no motion");
            // Frame 10: 8 cm above the last tracked height, reached over that frame: the mean rises 5 mm, then 1 cm a frame.
            for (int frame = 10; frame <= 24; frame++)
            {
                double y = solver.Step(1.08, true, Dt);
                double meanRise = frame >= 18 ? 0.08 : 0.005 + 0.01 * (frame - 10);
                Assert.That(y, Is.EqualTo(1.0 + gain * meanRise).Within(Exact), $"frame {frame}");
            }
        }

        /// <summary>A hold begun before the hand was seen (a NaN start) takes the first usable height as where the hand was
        /// (and had rested): that frame is still, and the object follows from the next one.</summary>
        [Test]
        public void AHoldBegunBeforeTheHandWasSeenFollowsFromItsFirstHeight()
        {
            var solver = new PaperLiteralSolver(2);
            solver.BeginHold(double.NaN, 0.5);
            double gain = PaperGain(2);
            Assert.That(solver.Step(double.NaN, false, Dt), Is.EqualTo(0.5));
            Assert.That(solver.Step(1.0, true, Dt), Is.EqualTo(0.5), "the first height seen is where the hand was");
            // Frame 3: the hand rose 8 cm over the frame: its mean over the last second rose 5 mm; then 1 cm a frame.
            Assert.That(solver.Step(1.08, true, Dt), Is.EqualTo(0.5 + gain * 0.005).Within(Exact));
            Assert.That(solver.Step(1.08, true, Dt), Is.EqualTo(0.5 + gain * 0.015).Within(Exact));
        }

        /// <summary>A frame time so long (10¹⁶ s and more: finite and positive, so a frame) that a clock could no longer
        /// advance by the unit time: the window is that frame's last second, the object never freezes, and a second after
        /// the hand moves the object has moved G times as far.</summary>
        [TestCase(1e16)]
        [TestCase(1e300)]
        public void AnAbsurdlyLongFrameNeverFreezesTheObject(double hugeDt)
        {
            var solver = new PaperLiteralSolver(2);
            solver.BeginHold(1.0, 1.0);
            Assert.That(solver.Step(1.0, true, hugeDt), Is.EqualTo(1.0));
            double gain = PaperGain(2);
            Assert.That(solver.Step(1.08, true, Dt), Is.EqualTo(1.0 + gain * 0.005).Within(Exact), "the mean rises 5 mm over the frame");
            for (int frame = 0; frame < 8; frame++) solver.Step(1.08, true, Dt);
            Assert.That(solver.ObjectY, Is.EqualTo(1.0 + gain * 0.08).Within(Exact));
        }

        /// <summary>A frame shorter than 0.1 ms is not a frame: under a new pose its Δy / dt is absurd (0.45 m in 1e-9 s), and
        /// the window would keep that speed for a second and throw the object hundreds of kilometres (545,955 m, found by
        /// FsCheck: SolverProperties.GarbageNeverReachesTheObject in Tests/Kosmos.PseudoHaptic.Properties.Tests). Nothing
        /// happens on it, and the next frame measures the move: the hold goes on bit for bit as if it had not come.</summary>
        [TestCase(0.01, 1e-9)]
        [TestCase(2.0, 1e-9)]
        [TestCase(2.0, 0.99e-4)]
        public void AFrameShorterThanATenthOfAMillisecondIsNotAFrame(double massKg, double instant)
        {
            const double frame = 1.0 / 90;
            var with = new PaperLiteralSolver(massKg);
            var without = new PaperLiteralSolver(massKg);
            with.BeginHold(1.0, 1.0);
            without.BeginHold(1.0, 1.0);
            Assert.That(with.Step(1.0, true, frame), Is.EqualTo(without.Step(1.0, true, frame)));
            Assert.That(with.Step(1.45, true, instant), Is.EqualTo(1.0), "the instant moves nothing");
            for (int i = 0; i < 200; i++)
                Assert.That(with.Step(1.45, true, frame), Is.EqualTo(without.Step(1.45, true, frame)), "frame " + i);
            Assert.That(with.ObjectY, Is.GreaterThan(1.1), "the move was measured, by the frame after the instant");
        }

        /// <summary>A hand that jumps a hundred kilometres and back (tracked, each height usable) under a light object (10 g
        /// leads the hand 2.7 times) makes v_final absurd: only a height a pose could have is
        /// taken (within ±10⁵ m, as the pipeline keeps it), so the object never leaves it.</summary>
        [Test]
        public void AnAbsurdSpeedNeverThrowsTheObjectBeyondAPosesReach()
        {
            var solver = new PaperLiteralSolver(0.01);
            solver.BeginHold(1.0, 1.0);
            double[] hands = { 1.0, -99999.0, 99999.0, -99999.0, 1.0 };
            foreach (double dt in new[] { 1.0 / 90, 3600.0 })
                for (int i = 0; i < 400; i++)
                    Assert.That(Math.Abs(solver.Step(hands[i % hands.Length], true, dt)), Is.LessThanOrEqualTo(WeightSolver.MaxCoordinate), "frame " + i + ", dt " + dt);
        }

        /// <summary>Frames of 0.3 s, which do not divide the second: the window's edge cuts a frame's piece of the hand's path.
        /// The hand rises 0.3 m over the first frame and rests; its mean height over the last second, by hand: 1.045 at 0.3 s
        /// (0.7 s of rest, the ramp's 0.3 s at 1.15), 1.135, 1.225, then 1.295 at 1.2 s (the ramp's last 0.1 s at 1.25 and
        /// 0.9 s at 1.3) and 1.3.</summary>
        [Test]
        public void AFrameTheSecondsEdgeCutsCountsForThePartInsideIt()
        {
            var solver = new PaperLiteralSolver(2);
            solver.BeginHold(1.0, 1.0);
            double gain = PaperGain(2);
            double[] means = { 1.045, 1.135, 1.225, 1.295, 1.3, 1.3 };
            for (int k = 0; k < means.Length; k++)
                Assert.That(solver.Step(1.3, true, 0.3), Is.EqualTo(1.0 + gain * (means[k] - 1.0)).Within(Exact), $"at {0.3 * (k + 1):0.0} s");
        }

        /// <summary>The documented shortest frame, 0.1 ms, is a frame (shorter ones are not).</summary>
        [Test]
        public void AFrameOfATenthOfAMillisecondIsAFrame()
        {
            var solver = new PaperLiteralSolver(GolfBallKg);
            solver.BeginHold(1.0, 1.0);
            Assert.That(solver.Step(1.5, true, 1e-4), Is.GreaterThan(1.0));
        }

        /// <summary>The window keeps the last second and drops what is older: held for minutes, the solver stops allocating
        /// once its lists hold a second of frames (they grew without end if nothing was dropped).</summary>
        [Test]
        public void TheWindowKeepsOnlyTheLastSecond()
        {
            var solver = new PaperLiteralSolver(2);
            solver.BeginHold(1.0, 1.0);
            int frame = 0;
            Allocation.AssertNone(n =>
            {
                for (int i = 0; i < n; i++, frame++) solver.Step(1.0 + 0.1 * Math.Sin(frame * 0.01), true, 1.0 / 90);
            }, "90 Hz frames of a held paper-literal object");
        }

        [TestCase(0.0)]
        [TestCase(-1.0)]
        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void AMassThatIsNotAFinitePositiveNumberIsRefusedNamingIt(double massKg)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new PaperLiteralSolver(massKg));
            Assert.That(e.ParamName, Is.EqualTo("massKg"));
            Assert.That(e.Message, Does.Contain("finite number greater than 0"));
        }

        [TestCase(double.Epsilon)]
        [TestCase(0.001)]
        [TestCase(1e6)]
        [TestCase(double.MaxValue)]
        public void AnyFinitePositiveMassIsAccepted(double massKg)
        {
            Assert.That(new PaperLiteralSolver(massKg).MassKg, Is.EqualTo(massKg));
        }
    }
}
