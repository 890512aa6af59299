using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// <see cref="PaperLiteralSolver"/>, the paper as printed (ALGORITHM.md §12), against hand computations: Eq. 1, 2, 4, 5
    /// and 6 in their relative reading with the paper's own constants (g = 9.80665 m/s², the golf ball's 0.045 kg, Eq. 5's
    /// 1.6793 m/s and 0.24 /kg, written here, not taken from the solver), the hand's speed averaged over the unit time of
    /// 1 s, and what it must absorb: a bad frame time, an untracked frame, a hold begun before the hand was seen, a hold
    /// begun after another one. Frames are 1/8 s long so that the clock is exact and the last second is exactly 8 frames.
    /// </summary>
    public class PaperLiteralSolverTests
    {
        const double G = 9.80665, GolfBallKg = 0.045, CurveA = 1.6793, CurveB = 0.24;
        const double Dt = 0.125;
        const double Exact = 1e-12;

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
        /// replaying the paper's equations gets them as written. One frame of 1 cm in 1/8 s (0.08 m/s, the window's only
        /// sample), 200 masses from 1 g to 20 kg.</summary>
        [Test]
        public void AtCueStrengthOneEachFrameIsEquationSixAsPrintedBitForBit()
        {
            var rng = new Random(6);
            int differs = 0;
            for (int i = 0; i < 200; i++)
            {
                double massKg = 0.001 * Math.Pow(20000, rng.NextDouble());
                var solver = new PaperLiteralSolver(massKg);
                solver.BeginHold(1.0, 1.0);
                double vReal = (1.01 - 1.0) / Dt;
                double weight = massKg * G, standardWeight = GolfBallKg * G;
                double vVirtual = vReal * standardWeight / weight;
                double vExp = CurveA * Math.Exp(-CurveB * massKg), vExpStandard = CurveA * Math.Exp(-CurveB * GolfBallKg);
                double printed = 1.0 + (vVirtual + vReal * vExp / vExpStandard) / 2 * Dt;
                double gainForm = 1.0 + vReal * ((standardWeight / weight + vExp / vExpStandard) / 2) * Dt;
                if (printed != gainForm) differs++;
                Assert.That(solver.Step(1.01, true, Dt), Is.EqualTo(printed), $"{massKg} kg");
            }
            Assert.That(differs, Is.GreaterThan(0), "the two forms round apart for some masses, so the test can tell them");
        }

        /// <summary>The hand rests for a second, jumps 8 cm in one frame and rests again: the last second's mean speed is
        /// 8 cm/s for exactly the 8 frames that hold the jump, so the object climbs G^s · 1 cm on each of them (v·dt, Eq. 6)
        /// and then stands still, G^s · 8 cm above where it was.</summary>
        [Test]
        public void AOneFrameMoveIsSpreadEvenlyOverTheNextSecond([Values(0.01, 0.045, 0.5, 2, 5)] double massKg, [Values(1.0, 0.5, 2.0)] double strength)
        {
            var solver = new PaperLiteralSolver(massKg) { CueStrength = strength };
            solver.BeginHold(1.0, 1.0);
            double gain = Math.Pow(PaperGain(massKg), strength), step = 0.08;
            for (int frame = 1; frame <= 32; frame++)
            {
                double hand = frame < 9 ? 1.0 : 1.0 + step;
                double y = solver.Step(hand, true, Dt);
                int framesOfTheJumpSoFar = Math.Min(Math.Max(frame - 8, 0), 8);
                double expected = 1.0 + gain * step / 8 * framesOfTheJumpSoFar;
                Assert.That(y, Is.EqualTo(expected).Within(Exact), $"frame {frame} (t = {frame * Dt} s)");
            }
            Assert.That(solver.ObjectY - 1.0, Is.EqualTo(gain * step).Within(Exact), "the object ends G^s times the hand's move above");
        }

        /// <summary>"The unit time for measuring the average speed is 1 s": a steady lift's mean speed is the hand's speed,
        /// and a second after the hand stops the window holds only still frames.</summary>
        [Test]
        public void ASteadyLiftMovesAtTheGainAndStopsOneSecondAfterTheHand()
        {
            var solver = new PaperLiteralSolver(1);
            solver.BeginHold(0.5, 0.5);
            double gain = PaperGain(1), speed = 0.4, hand = 0.5;
            double[] path = new double[40];
            for (int frame = 1; frame <= 40; frame++)
            {
                if (frame <= 16) hand += speed * Dt;     // 2 s at 0.4 m/s, then still
                path[frame - 1] = solver.Step(hand, true, Dt);
            }
            // While the lift goes on the mean speed is 0.4 m/s on every frame (the window fills with equal speeds).
            for (int frame = 1; frame <= 16; frame++)
                Assert.That(path[frame - 1], Is.EqualTo(0.5 + gain * speed * Dt * frame).Within(Exact), $"frame {frame}");
            // After the stop, frame 16 + k holds 8 − k moving frames of the last 8.
            double y = path[15];
            for (int k = 1; k <= 8; k++)
            {
                y += gain * speed * (8 - k) / 8 * Dt;
                Assert.That(path[15 + k], Is.EqualTo(y).Within(Exact), $"{k} frame(s) after the stop");
            }
            for (int frame = 25; frame <= 40; frame++)
                Assert.That(path[frame - 1], Is.EqualTo(path[23]), $"frame {frame}: still a second after the hand");
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
        /// height beyond ±10⁵ m) is a still frame: the object does not move, and the next tracked height is measured from
        /// the last tracked one, so the move is spread over the next second as any other.</summary>
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
            // Frame 10: 8 cm above the last tracked height; the mean over frames 3..10 is 8 cm/s for 8 frames.
            for (int frame = 10; frame <= 24; frame++)
            {
                double y = solver.Step(1.08, true, Dt);
                double expected = 1.0 + gain * 0.01 * Math.Min(frame - 9, 8);
                Assert.That(y, Is.EqualTo(expected).Within(Exact), $"frame {frame}");
            }
        }

        /// <summary>A hold begun before the hand was seen (a NaN start) takes the first usable height as where the hand was:
        /// that frame is still, and the object follows from the next one, the window's mean taken over the frames it holds.</summary>
        [Test]
        public void AHoldBegunBeforeTheHandWasSeenFollowsFromItsFirstHeight()
        {
            var solver = new PaperLiteralSolver(2);
            solver.BeginHold(double.NaN, 0.5);
            double gain = PaperGain(2);
            Assert.That(solver.Step(double.NaN, false, Dt), Is.EqualTo(0.5));
            Assert.That(solver.Step(1.0, true, Dt), Is.EqualTo(0.5), "the first height seen is where the hand was");
            // Frame 3: the hand rose 8 cm (0.64 m/s); the window holds 3 frames, mean 0.64/3 m/s.
            Assert.That(solver.Step(1.08, true, Dt), Is.EqualTo(0.5 + gain * 0.64 / 3 * Dt).Within(Exact));
            Assert.That(solver.Step(1.08, true, Dt), Is.EqualTo(0.5 + gain * (0.64 / 3 + 0.64 / 4) * Dt).Within(Exact));
        }

        /// <summary>A frame time so long (10¹⁶ s and more: finite and positive, so a frame) that the clock can no longer
        /// advance by the unit time leaves the window its current frame: the object never freezes, it follows the hand at
        /// the gain G frame by frame.</summary>
        [TestCase(1e16)]
        [TestCase(1e300)]
        public void AnAbsurdlyLongFrameNeverFreezesTheObject(double hugeDt)
        {
            var solver = new PaperLiteralSolver(2);
            solver.BeginHold(1.0, 1.0);
            Assert.That(solver.Step(1.0, true, hugeDt), Is.EqualTo(1.0));
            double gain = PaperGain(2);
            Assert.That(solver.Step(1.08, true, Dt), Is.EqualTo(1.0 + gain * 0.08).Within(Exact), "8 cm at once, the window one frame");
            Assert.That(solver.Step(1.08, true, Dt), Is.EqualTo(1.0 + gain * 0.08).Within(Exact));
            Assert.That(solver.Step(1.0, true, Dt), Is.EqualTo(1.0).Within(Exact));
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

        /// <summary>A hand that jumps a hundred kilometres and back (tracked, each height usable) under a light object (the
        /// literal gain has no cap: 10 g leads the hand 2.7 times) makes v_final absurd: only a height a pose could have is
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
