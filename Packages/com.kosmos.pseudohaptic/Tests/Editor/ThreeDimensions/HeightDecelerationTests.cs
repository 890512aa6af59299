using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>
    /// Issue 23, height deceleration a user can see: on a constant-speed 0.25 m lift the upper fifth rises at least 10 %
    /// slower than the lower fifth at 2 kg, more at 5 kg, less at 1 kg, never stalling; the standard weight untouched;
    /// lowering past where the lift began unaffected; a lift and a lowering end where they began (a function of the lift).
    /// </summary>
    public class HeightDecelerationTests
    {
        /// <summary>How much slower the object rises while the hand goes through the upper fifth of a constant-speed 0.25 m lift
        /// than through the lower fifth: 1 − (rise in the upper fifth) / (rise in the lower fifth).</summary>
        static double Slowing(double massKg, double speed, string profile = "xyz")
        {
            // Poses at 90 Hz on every frame, on time: the object's motion is read against exact hand heights.
            var s = new WeightSolver3D(WeightModel.FromMass(massKg), NamedProfiles.Get(profile), 0.5);
            double y0 = 0.8, dt = 1 / 90.0, rise = 0.25;
            s.BeginHold(new HandPose(0, y0, 0, true, true, 0), 0, y0, 0);
            for (int i = 1; i <= 45; i++) s.Step(new HandPose(0, y0, 0, true, true, i * dt), dt); // rest: the grab settles
            // The object's rise per metre of the hand's over the lower and the upper fifth, from the frames at their ends.
            double lowH0 = 0, lowY0 = s.ObjectY, lowH1 = double.NaN, lowY1 = 0, upH0 = 0, upY0 = 0, upY1 = 0;
            for (int i = 1; ; i++)
            {
                double lifted = Math.Min(rise, speed * i * dt);
                s.Step(new HandPose(0, y0 + lifted, 0, true, true, (45 + i) * dt), dt);
                if (double.IsNaN(lowH1) && lifted >= 0.05 - 1e-12) { lowH1 = lifted; lowY1 = s.ObjectY; }
                if (lifted <= 0.20 + 1e-12) { upH0 = lifted; upY0 = s.ObjectY; }
                if (lifted >= rise - 1e-12) { upY1 = s.ObjectY; break; }
            }
            return 1 - ((upY1 - upY0) / (rise - upH0)) / ((lowY1 - lowY0) / (lowH1 - lowH0));
        }

        [Test]
        public void TheUpperFifthRisesVisiblySlowerTheMoreTheHeavier([Values(0.25, 0.5, 1.0)] double speed)
        {
            double one = Slowing(1, speed), two = Slowing(2, speed), five = Slowing(5, speed);
            TestContext.Progress.WriteLine($"constant-speed 0.25 m lift at {speed} m/s, upper fifth slower than the lower by: 1 kg {one:P1}, 2 kg {two:P1}, 5 kg {five:P1}");
            Assert.That(two, Is.GreaterThanOrEqualTo(0.10), "2 kg: at least 10 % slower");
            Assert.That(five, Is.GreaterThan(two), "5 kg slows more");
            Assert.That(one, Is.LessThan(two).And.GreaterThan(0), "1 kg slows less, but slows");
            Assert.That(five, Is.LessThan(0.5), "never stalling: the floor fraction keeps at least half the speed");
            Assert.That(Slowing(2, speed, "paper"), Is.EqualTo(0).Within(0.005), "without it the gain is constant");
        }

        [Test]
        public void TheStandardWeightAndLighterAreUntouched([Values(0.001, 0.02, 0.045)] double massKg)
        {
            var frames = Run.Headset(frameRate: 90, jitterSd: 0.002, seed: 3).Render(HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.3, 0.8).Hold(0.3).MoveTo(0.6, 0.8).Hold(0.3));
            var with = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper.With(new HeightDeceleration())), frames);
            var without = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper), frames);
            Assert.That(with, Is.EqualTo(without));
        }

        [Test]
        public void ALiftAndALoweringEndWhereTheyBeganAndLoweringPastTheBaseIsUnaffected([Values(1.0, 5.0)] double massKg)
        {
            var profile = NamedProfiles.PaperExperiment.With(new HeightDeceleration());
            var frames = Run.Headset(frameRate: 90, seed: 4).Render(HandPath.StartAt(1.0).Hold(0.3).MoveTo(1.4, 1).Hold(0.3).MoveTo(1.0, 1).Hold(0.5).MoveTo(0.7, 0.8).Hold(0.5));
            var with = Run.Replay(Run.Solver(massKg, profile), frames);
            var without = Run.Replay(Run.Solver(massKg, NamedProfiles.PaperExperiment), frames);
            int back = Array.FindIndex(frames, f => f.Time >= 2.8);
            Assert.That(with[back], Is.EqualTo(1.0).Within(0.002), "back where it began: what the lift withheld the lowering gave back");
            for (int i = back; i < frames.Length; i++) Assert.That(with[i], Is.EqualTo(without[i]).Within(1e-9), "below where the lift began nothing changes, frame " + i);
        }

        [Test]
        public void AMassJustAboveTheStandardCarriesTheLiftToRounding()
        {
            // ln(1 + a·h)/a with a tiny (w = (1 − G)² → 0) lost every digit: 45.00000001 g lagged 10 cm under xyz and
            // 45.000001 g ended 1 cm above the hand. The reference: ln(1 + x)/x by its series where x is small, else
            // the plain logarithm (accurate there to 1e-13); within a part in 10¹² of the lift.
            var settings = new[] { new HeightDeceleration(), new HeightDeceleration(height: 100), new HeightDeceleration(height: 0.01, minFraction: 0.01), new HeightDeceleration(minFraction: 1) };
            foreach (var e in settings)
                for (int k = 1; k <= 17; k++)
                    foreach (double lift in new[] { 1e-6, 0.003, 0.2, 1.5 })
                    {
                        double g = 1 - Math.Pow(10, -k / 2.0), w = HeightDeceleration.Strength(g), x = w / e.Height * lift;
                        double ratio = x < 1e-3 ? 1 - x / 2 + x * x / 3 - x * x * x / 4 + x * x * x * x / 5 : Math.Log(1 + x) / x;
                        double expected = e.MinFraction * lift + (1 - e.MinFraction) * lift * ratio;
                        double carried = e.CarriedLift(lift, g);
                        Assert.That(carried, Is.EqualTo(expected).Within(1e-12 * lift), $"height {e.Height}, φ {e.MinFraction}, G = 1 − 10^{-k / 2.0}, lift {lift}");
                        Assert.That(carried, Is.LessThanOrEqualTo(lift).And.GreaterThanOrEqualTo(e.MinFraction * lift), "between the floor and the lift");
                    }

            // In the headset: objects a hair heavier than the golf ball stay in the hand, as the golf ball does.
            var frames = Run.Headset(frameRate: 90, jitterSd: 0.001, seed: 5).Render(HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.0, 0.6).Hold(0.5));
            foreach (double mass in new[] { 0.04500000001, 0.0450000003, 0.045000001, 0.045000003 })
            {
                var with = Run.Replay(Run.Solver(mass, NamedProfiles.Paper.With(new HeightDeceleration())), frames);
                var without = Run.Replay(Run.Solver(mass, NamedProfiles.Paper), frames);
                for (int i = 0; i < with.Length; i++)
                    Assert.That(with[i], Is.EqualTo(without[i]).Within(1e-6), $"{mass} kg, frame {i}");
            }
        }

        [Test]
        public void TheFactorAndTheLiftItCarriesAreTheDocumentedCurve()
        {
            var e = new HeightDeceleration();
            double g = 0.32, w = HeightDeceleration.Strength(g);
            Assert.That(w, Is.EqualTo((1 - g) * (1 - g)).Within(1e-15));
            Assert.That(e.Factor(0, g), Is.EqualTo(1));
            Assert.That(e.Factor(0.25, g), Is.EqualTo(0.5 + 0.5 / (1 + w * 0.25 / 0.125)).Within(1e-15));
            Assert.That(e.Factor(100, g), Is.GreaterThan(0.5), "never below the floor fraction");
            Assert.That(e.Factor(0.25, 1), Is.EqualTo(1), "the standard weight");
            // F is the integral of f: compare with the midpoint rule over 0.4 m.
            double sum = 0;
            for (int i = 0; i < 4000; i++) sum += e.Factor((i + 0.5) * 1e-4, g) * 1e-4;
            Assert.That(e.CarriedLift(0.4, g), Is.EqualTo(sum).Within(1e-9));
            Assert.That(e.CarriedLift(-0.1, g), Is.EqualTo(-0.1), "below the base, nothing withheld");
            Assert.That(() => new HeightDeceleration(height: 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("height"));
            Assert.That(() => new HeightDeceleration(minFraction: 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("minFraction"));
            Assert.That(e.Name, Is.EqualTo("height-deceleration"));
        }
    }
}
