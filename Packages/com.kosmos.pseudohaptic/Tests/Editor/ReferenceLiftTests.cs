using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The reference lift (<see cref="ReferenceLift"/>, issue 31): 0.3 s at rest at 0.8 m, a minimum-jerk rise of 0.2 m, 0.5 s
    /// at rest; 90 Hz frames with a new pose each, no latency, no jitter; the end lag through the solver or, for
    /// <c>paper-literal</c>, through <see cref="PaperLiteralSolver"/>; its arguments checked.
    /// </summary>
    public class ReferenceLiftTests
    {
        [TestCase(0.6), TestCase(1.2)]
        public void EachFrameShowsTheHandWhereItIsThenAt90Hz(double seconds)
        {
            var frames = ReferenceLift.Frames(seconds);
            var path = HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.0, seconds).Hold(0.5);
            Assert.That(frames[0].Time, Is.EqualTo(0));
            Assert.That(frames[frames.Length - 1].Time, Is.EqualTo(0.3 + seconds + 0.5).Within(1.0 / 90));
            for (int i = 0; i < frames.Length; i++)
            {
                if (i > 0) Assert.That(frames[i].Time - frames[i - 1].Time, Is.EqualTo(1.0 / 90).Within(1e-9), $"frame {i}");
                Assert.That(frames[i].Tracked, Is.True);
                Assert.That(frames[i].HandY, Is.EqualTo(path.HeightAt(frames[i].Time)).Within(1e-12), $"frame {i}: a new pose, no latency, no jitter");
            }
        }

        [Test]
        public void BadArgumentsThrowNamingThem()
        {
            Assert.That(() => ReferenceLift.Frames(0), Throws.TypeOf<ArgumentOutOfRangeException>()
                .With.Property("ParamName").EqualTo("seconds").And.Message.Contains("finite"), "finite and > 0");
            var frames = ReferenceLift.Frames();
            Assert.That(() => ReferenceLift.EndLag(null, 1, WeightSolver.DefaultStandardSpeed, 1, frames),
                Throws.TypeOf<ArgumentNullException>().With.Property("ParamName").EqualTo("profile"));
            Assert.That(() => ReferenceLift.EndLag(NamedProfiles.PaperLiteral, 1, WeightSolver.DefaultStandardSpeed, 1, frames),
                Throws.Nothing, "paper-literal is a profile like the others");
            foreach (var bad in new[] { null, new TraceFrame[0], new[] { frames[0] } })
                Assert.That(() => ReferenceLift.EndLag(NamedProfiles.PaperExperiment, 1, WeightSolver.DefaultStandardSpeed, 1, bad),
                    Throws.ArgumentException.With.Property("ParamName").EqualTo("frames").And.Message.Contains("needs frames"));
            var two = new[] { new TraceFrame(0, 0.8), new TraceFrame(1.0 / 90, 0.801) };
            Assert.That(ReferenceLift.EndLag(NamedProfiles.PaperExperiment, 1, WeightSolver.DefaultStandardSpeed, 1, two), Is.InRange(0.0, 0.001), "two frames are a lift");
        }

        [TestCase(0.6, 1.0), TestCase(2.0, 1.0), TestCase(2.0, 3.0), TestCase(0.6, 1.0 / 3)]
        public void PaperLiteralEndsWherePaperLiteralSolverEnds(double massKg, double s)
        {
            var frames = ReferenceLift.Frames();
            var literal = new PaperLiteralSolver(massKg) { CueStrength = s };
            literal.BeginHold(frames[0].HandY, frames[0].HandY);
            for (int i = 1; i < frames.Length; i++) literal.Step(frames[i].HandY, frames[i].Tracked, frames[i].Time - frames[i - 1].Time);
            double expected = frames[frames.Length - 1].HandY - literal.ObjectY;
            Assert.That(ReferenceLift.EndLag(NamedProfiles.PaperLiteral, massKg, WeightSolver.DefaultStandardSpeed, s, frames), Is.EqualTo(expected).Within(1e-12));
            Assert.That(ReferenceLift.EndLag(NamedProfiles.PaperLiteral, massKg, WeightSolver.DefaultStandardSpeed, s), Is.EqualTo(expected).Within(1e-12), "the default frames are these");
        }

        [Test]
        public void UnderPaperLiteralAHeavierObjectAndAStrongerCueLagMore()
        {
            double Lag(double m, double s) => ReferenceLift.EndLag(NamedProfiles.PaperLiteral, m, WeightSolver.DefaultStandardSpeed, s);
            Assert.That(Lag(2.0, 1), Is.GreaterThan(Lag(0.6, 1)));
            Assert.That(Lag(2.0, 3), Is.GreaterThan(Lag(2.0, 1)));
            Assert.That(Lag(2.0, 1), Is.GreaterThan(0).And.LessThan(ReferenceLift.Rise), "behind the hand, not below the start");
        }
    }
}
