using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>Issue 10, lateral inertia: heavier trails the hand's horizontal motion more; the standard weight and
    /// lighter follow exactly; no overshoot, no oscillation; bounded by 0.10 m; decays under 1 cm within 1 s of the
    /// hand stopping; the same end point at any frame clock.</summary>
    public class LateralInertiaTests
    {
        static readonly WeightProfile Profile = NamedProfiles.Paper.With(new LateralInertia(), "paper+lateral");

        /// <summary>A sideways carry of <paramref name="distance"/> m in <paramref name="seconds"/>, at 0.5 s, then a hold.</summary>
        static HandPath3D Carry(double distance = 0.5, double seconds = 0.8, double diagonal = 0)
            => (double t, out double x, out double y, out double z) =>
            {
                double s = Headset3D.MinJerk(t, 0.5, seconds, 0, 1);
                x = 0.1 + distance * s;
                y = 1.0;
                z = 0.3 + diagonal * s;
            };

        static Run3D RunCarry(double massKg, WeightProfile profile, Headset3D headset = null, HandPath3D path = null, double duration = 3.5)
        {
            var frames = (headset ?? new Headset3D()).Render(path ?? Carry(), null, duration);
            return Run3D.Of(new WeightSolver3D(WeightModel.FromMass(massKg), profile), frames);
        }

        static double MaxLag(Run3D r)
        {
            double m = 0;
            for (int i = 0; i < r.X.Length; i++) m = Math.Max(m, r.FollowedX[i] - r.X[i]);
            return m;
        }

        [Test]
        public void HeavierTrailsMoreTheStandardAndLighterFollowExactly()
        {
            double previous = -1;
            foreach (double m in new[] { 0.1, 0.3, 0.5, 1, 2, 5, 20 })
            {
                // 0.2 m in 1.5 s: slow enough that no mass reaches the bound.
                double lag = MaxLag(RunCarry(m, Profile, path: Carry(0.2, 1.5)));
                Assert.That(lag, Is.LessThan(0.095), "below the bound, where mass still tells");
                Assert.That(lag, Is.GreaterThan(previous + 1e-4), $"{m} kg trails more than the lighter one");
                previous = lag;
            }
            foreach (double m in new[] { 0.001, 0.01, 0.045 })
            {
                var r = RunCarry(m, Profile);
                for (int i = 0; i < r.X.Length; i++)
                {
                    Assert.That(r.X[i], Is.EqualTo(r.FollowedX[i]), $"{m} kg x at frame {i}");
                    Assert.That(r.Z[i], Is.EqualTo(r.FollowedZ[i]), $"{m} kg z at frame {i}");
                }
            }
        }

        [Test]
        public void ProfilesWithoutItFollowTheHandOneToOne([Values("paper", "paper-experiment", "gain")] string name)
        {
            var headset = new Headset3D { JitterSd = 0.002, Seed = 4 };
            var frames = headset.Render(Carry(0.4, 0.6, 0.3), null, 3);
            var r = Run3D.Of(new WeightSolver3D(WeightModel.FromMass(5), NamedProfiles.Get(name)), frames, objectX: 0.2, objectZ: 0.1);
            for (int i = 0; i < r.X.Length; i++)
            {
                Assert.That(r.X[i] - frames.A[i].X, Is.EqualTo(0.2 - frames.A[0].X).Within(1e-12), $"x at frame {i}");
                Assert.That(r.Z[i] - frames.A[i].Z, Is.EqualTo(0.1 - frames.A[0].Z).Within(1e-12), $"z at frame {i}");
            }
        }

        [Test]
        public void NeverOvershootsNeverOscillatesBoundedAndDecays([Values(0.3, 1, 5, 1000)] double massKg, [Values(30.0, 72.0, 90.0, 120.0)] double fps)
        {
            // 0.6 m in 0.4 s: a fast swing, mean 1.5 m/s, that saturates the bound for heavy objects.
            var r = RunCarry(massKg, Profile, new Headset3D { FrameRate = fps, Seed = 3 }, Carry(0.6, 0.4, 0.2), 3);
            var frames = new Headset3D { FrameRate = fps, Seed = 3 }.Render(Carry(0.6, 0.4, 0.2), null, 3);
            double lastPose = 0.5 + 0.4 + 0.045 + 1 / 30.0; // the hand's last moving pose has reached the frames by then
            double prevLag = double.PositiveInfinity;
            for (int i = 0; i < r.X.Length; i++)
            {
                double lx = r.FollowedX[i] - r.X[i], lz = r.FollowedZ[i] - r.Z[i];
                double lag = Math.Sqrt(lx * lx + lz * lz);
                Assert.That(lx, Is.GreaterThanOrEqualTo(-1e-12), "x never past the hand");
                Assert.That(lz, Is.GreaterThanOrEqualTo(-1e-12), "z never past the hand");
                Assert.That(lag, Is.LessThanOrEqualTo(0.10 + 1e-9), "the documented bound, 0.10 m");
                if (i > 0) Assert.That(r.X[i], Is.GreaterThanOrEqualTo(r.X[i - 1] - 1e-12), "the object never moves back: no oscillation");
                if (frames.T[i] >= lastPose)
                {
                    Assert.That(lag, Is.LessThanOrEqualTo(prevLag + 1e-15), "after the hand stops the lag only shrinks");
                    prevLag = lag;
                    if (frames.T[i] >= lastPose + 1) Assert.That(lag, Is.LessThan(0.01), "under 1 cm within 1 s");
                }
            }
        }

        [Test]
        public void SameEndPointAtAnyFrameClock([Values(0.2, 2, 50)] double massKg)
        {
            double? reference = null, referenceZ = null;
            foreach (var h in new[]
            {
                new Headset3D { FrameRate = 30 }, new Headset3D { FrameRate = 60, PoseRate = 60 }, new Headset3D { FrameRate = 72 },
                new Headset3D { FrameRate = 90, Wobble = 0.3, Seed = 8 }, new Headset3D { FrameRate = 120, Wobble = 0.5, Seed = 9 },
            })
            {
                var r = RunCarry(massKg, NamedProfiles.Xyz, h, Carry(0.5, 0.8, -0.3), 4);
                double x = r.X[r.X.Length - 1], z = r.Z[r.Z.Length - 1];
                reference = reference ?? x;
                referenceZ = referenceZ ?? z;
                Assert.That(x, Is.EqualTo(reference.Value).Within(0.001), $"x at {h.FrameRate} Hz");
                Assert.That(z, Is.EqualTo(referenceZ.Value).Within(0.001), $"z at {h.FrameRate} Hz");
            }
            Assert.That(reference.Value, Is.EqualTo(0.6).Within(0.001), "ends where the hand put it");
        }

        [Test]
        public void TheLagIsAFirstOrderFilterPerFrameBoundedAndDecayingOverAtMostATenthOfASecondPerFrame()
        {
            // Each frame the lateral lag e (hand − object, sideways) becomes (e + the hand's step)·τ/(τ + dt), its length
            // at most MaxOffset (0.1 m), dt counting at most 0.1 s (a hitch does not erase it at once).
            var s = new WeightSolver3D(WeightModel.FromMass(2), NamedProfiles.Xyz);
            double tau = new LateralInertia().TimeConstantFor(s.Vertical.Gain), t = 0, hx = 0, hz = 0, ex = 0, ez = 0;
            Assert.That(tau, Is.GreaterThan(0.05), "2 kg trails");
            s.BeginHold(new HandPose(0, 1, 0, true, true, t), 0, 1, 0);
            double[] stepX = { 0.02, 0.02, 0.02, 0.15, 0.15, 0.15, 0, 0, 0, 0 }, stepZ = { 0.01, 0.01, 0.01, -0.05, 0, 0, 0, 0, 0, 0 };
            for (int i = 0; i < stepX.Length; i++)
            {
                t += 1 / 32.0; hx += stepX[i]; hz += stepZ[i];
                s.Step(new HandPose(hx, 1, hz, true, true, t), 1 / 32.0);
                double k = tau / (tau + 1 / 32.0);
                ex = (ex + stepX[i]) * k; ez = (ez + stepZ[i]) * k;
                double n = Math.Sqrt(ex * ex + ez * ez);
                if (n > 0.1) { ex *= 0.1 / n; ez *= 0.1 / n; }
                Assert.That(s.LagX, Is.EqualTo(ex).Within(1e-12), "pose " + i);
                Assert.That(s.LagZ, Is.EqualTo(ez).Within(1e-12), "pose " + i);
                Assert.That(s.ObjectX, Is.EqualTo(hx - ex).Within(1e-12), "pose " + i);
                Assert.That(s.ObjectZ, Is.EqualTo(hz - ez).Within(1e-12), "pose " + i);
            }
            double x = s.ObjectX, z = s.ObjectZ, lag = s.LagX, lagZ = s.LagZ;
            Assert.That(lagZ, Is.Not.EqualTo(0), "a lag in z too");
            t += 0.5;
            s.Step(new HandPose(hx, 1, hz, true, true, t), 0.5); // a half-second hitch
            Assert.That(s.LagX, Is.EqualTo(lag * tau / (tau + 0.1)).Within(1e-12), "decayed as over 0.1 s");
            Assert.That(s.LagZ, Is.EqualTo(lagZ * tau / (tau + 0.1)).Within(1e-12));
            Assert.That(s.ObjectX, Is.EqualTo(x + lag - s.LagX).Within(1e-12), "the object closes that much of the lag");
            Assert.That(s.ObjectZ, Is.EqualTo(z + lagZ - s.LagZ).Within(1e-12));
        }

        [Test]
        public void TheTimeConstantIsTauTimesOneMinusGAndNoneForTheStandardOrLighter()
        {
            var e = new LateralInertia();
            Assert.That(e.TimeConstantFor(0.5), Is.EqualTo(0.15).Within(1e-15), "0.3 s × (1 − 0.5)");
            Assert.That(e.TimeConstantFor(0.0), Is.EqualTo(0.3));
            Assert.That(e.TimeConstantFor(1.0), Is.EqualTo(0.0), "the standard weight follows exactly");
            Assert.That(e.TimeConstantFor(3.0), Is.EqualTo(0.0), "lighter too, never a negative lag");
            Assert.That(new LateralInertia(timeConstant: 1).TimeConstantFor(0.25), Is.EqualTo(0.75));
        }

        [Test]
        public void InvalidSettingsNameTheField()
        {
            Assert.That(() => new LateralInertia(timeConstant: -1), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("timeConstant"));
            Assert.That(() => new LateralInertia(timeConstant: double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("timeConstant"));
            Assert.That(() => new LateralInertia(maxOffset: 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("maxOffset"));
            Assert.That(() => new LateralInertia(maxOffset: double.PositiveInfinity), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("maxOffset"));
        }
    }
}
