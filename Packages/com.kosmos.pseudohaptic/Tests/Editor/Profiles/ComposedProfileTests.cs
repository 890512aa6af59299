using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Cases the generated properties over composed profiles found (Tests/Kosmos.PseudoHaptic.Properties.Tests,
    /// ComposedProfileProperties), each shrunk: the fixed ones as tests, the open ones explicit, each saying why.
    /// </summary>
    public class ComposedProfileTests
    {
        /// <summary>
        /// The finite guard (ALGORITHM.md §3, step 11) keeps the object, not only the point the hand holds
        /// (<see cref="MotionFrame.NewObjectY"/>: the object plus the grab offset), within ±10⁵ m. Here the object begins at
        /// 99,999 m with the hand at 0 (both valid: <see cref="WeightSolver.BeginHold"/> accepts either within ±10⁵ m) and
        /// the hand lifts 12 m: the 1 g object ended at 100,034.97 m under <c>gain</c> (100,011.17 under <c>paper</c>) when
        /// the guard judged the held point alone. A composed profile reached it with a floor near 10⁵ m (floor-clamp's range
        /// is ±10⁵ m): the floor raises the object at the grab, and any lift takes it past.
        /// </summary>
        [Test]
        public void AnObjectThatBeginsFarFromTheHandStaysWithinTheCoordinateRange([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            var solver = new WeightSolver(WeightModel.FromMass(0.001), NamedProfiles.Get(profile));
            solver.BeginHold(0, 99999, 0);
            double highest = double.NegativeInfinity;
            for (int i = 1; i <= 1800; i++)
                highest = Math.Max(highest, solver.Step(new HandSample(Math.Min(12.0, 12.0 * i / 900), true, true, i / 90.0), 1 / 90.0));
            Assert.That(highest, Is.LessThanOrEqualTo(WeightSolver.MaxCoordinate));
        }

        /// <summary>The same in 3D, sideways: an object grabbed 99,999 m aside of the hand, which then moves 12 m toward it, stays
        /// within ±10⁵ m on x (it ended at 100,011 m under every named profile), and keeps its height's guard too.</summary>
        [Test]
        public void AnObjectGrabbedFarAsideStaysWithinTheCoordinateRange([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            var solver = new WeightSolver3D(WeightModel.FromMass(0.001), NamedProfiles.Get(profile));
            solver.BeginHold(new HandPose(0, 1, 0, true, true, 0), 99999, 1, 0);
            double farthest = 0;
            for (int i = 1; i <= 1800; i++)
            {
                double x = Math.Min(12.0, 12.0 * i / 900);
                solver.Step(new HandPose(x, 1, 0, true, true, i / 90.0), 1 / 90.0);
                farthest = Math.Max(farthest, Math.Abs(solver.ObjectX));
            }
            Assert.That(farthest, Is.LessThanOrEqualTo(WeightSolver.MaxCoordinate));
            Assert.That(farthest, Is.GreaterThan(99999), "the object moved with the hand until the range's edge");
        }

        /// <summary>
        /// The same guard in 3D, on x and z: with the workspace radius at its largest (10⁵ m, valid), two hands followed in
        /// turn 10⁵ m apart re-anchor the followed point (the hands' mean plus the anchor that keeps it from stepping)
        /// 2 × 10⁵ m away; z was 199,999.98 m before <see cref="WeightSolver3D"/> kept x and z within ±10⁵ m. Shrunk by FsCheck
        /// from a garbage hold (ComposedProfileProperties.GarbageNeverReachesTheObjectUnderAnyComposedProfile, seed 3).
        /// </summary>
        [Test]
        public void TwoHandsFollowedInTurnAcrossTheLargestWorkspaceKeepTheObjectWithinTheCoordinateRange()
        {
            var profile = new WeightProfile("two-hands-wide", new WeightEffect[] { new TwoHands() }, new SolverLimits(maxHandSpeed: double.MaxValue, workspaceRadius: 1e5));
            var solver = new WeightSolver3D(WeightModel.FromMass(1), profile);
            solver.BeginHold(new HandPose(0, 1.725, 0), new HandPose(0.3, 1.725, 0), 0.15, 1.725, 0);
            var a = new HandPose(-0.0, 1.58632, 99999.99, true, true, 54.522);
            var b = new HandPose(double.NegativeInfinity, 1.33078, 0.92358, true, true, 19.061);
            var c = new HandPose(0, 1, 0, true, true, 29.781);
            solver.SetGrip(1, true); solver.Step(a, b, 1 / 72.0);
            solver.SetGrip(2, true); solver.Step(b, c, 1 / 72.0);
            solver.SetGrip(1, true); solver.Step(c, a, 1 / 90.0);
            Assert.That(Math.Abs(solver.ObjectZ), Is.LessThanOrEqualTo(WeightSolver.MaxCoordinate), "z " + solver.ObjectZ);
        }

        /// <summary>
        /// A glide far slower than the default outlasts the hold and keeps what it takes in: the base's own small moves at rest
        /// (the lowering guard at slack 0 following jitter down, a fast relaxation pulling it back up) piled up in it and moved
        /// the object at rest (1 kg, lowered 0.2 m, 10 s at rest with 1.5 mm of jitter, glideSpeed 5e-324: the glide grew to
        /// 7.5 mm and the object crept 6.4 mm; shrunk by FsCheck, ComposedProfileProperties, seed 1). The slowest glide is now
        /// <see cref="SolverLimits.MinGlideSpeed"/>, a centimetre a second, and there the object rests where the default glide
        /// leaves it, over 40 seeds.
        /// </summary>
        [Test]
        public void AtTheSlowestGlideTheObjectRestsWhereTheDefaultGlideLeavesIt()
        {
            var effects = new WeightEffect[] { new LoweringGuard(0), new OffsetRelaxation(0.01, 0.1), new ExperimentalBlend() };
            var slowest = new WeightProfile("slowest-glide", effects, new SolverLimits(glideSpeed: SolverLimits.MinGlideSpeed));
            var standard = new WeightProfile("default-glide", effects);
            double worst = 0;
            for (int seed = 1; seed <= 40; seed++)
            {
                var path = Simulation.HandPath.StartAt(0.8).Hold(0.5).MoveTo(0.6, 1.0).Hold(10.5);
                var frames = new Simulation.HeadsetSimulator { FrameRate = 90, PoseRate = 30, Latency = 0.045, JitterSd = 0.0015, LowConfidenceAboveSpeed = 0.6, LowConfidenceChance = 0.3, Seed = 90709 + seed }.Render(path);
                var slow = Simulation.TraceReplay.Run(new WeightSolver(WeightModel.FromMass(1), slowest), frames);
                var usual = Simulation.TraceReplay.Run(new WeightSolver(WeightModel.FromMass(1), standard), frames);
                for (int i = Array.FindIndex(frames, f => f.Time >= 2.0); i < frames.Length; i++) worst = Math.Max(worst, Math.Abs(slow[i] - usual[i]));
            }
            TestContext.WriteLine($"at rest, slowest glide against the default: {worst * 1000:F3} mm at most");
            Assert.That(worst, Is.LessThan(0.0005));
        }

        /// <summary>A glide slower than <see cref="SolverLimits.MinGlideSpeed"/> is refused when it is set, naming the setting.</summary>
        [TestCase(double.Epsilon)]
        [TestCase(0.001)]
        [TestCase(0.00999)]
        public void AGlideSlowerThanACentimetreASecondIsRefused(double glideSpeed)
            => Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new SolverLimits(glideSpeed: glideSpeed)).ParamName, Is.EqualTo("glideSpeed"));

        /// <summary>The slowest glide is a centimetre a second, and every finite glide from there up is one (the range has a
        /// least value and no greatest).</summary>
        [TestCase(0.01)]
        [TestCase(0.3)]
        [TestCase(double.MaxValue)]
        public void AGlideOfACentimetreASecondOrFasterIsAccepted(double glideSpeed)
            => Assert.That(new SolverLimits(glideSpeed: glideSpeed).GlideSpeed, Is.EqualTo(glideSpeed));

        /// <summary>In 3D as on y, ±10⁵ m itself is a coordinate: an object grabbed 99,999 m aside (on x or z) whose hand then
        /// moves 1 m toward the far side ends exactly 10⁵ m aside, followed to the range's edge.</summary>
        [Test]
        public void AnObjectMovedToExactly1E5AsideIsFollowedThere([Values(0, 2)] int axis, [Values(1.0, -1.0)] double sign)
        {
            var solver = new WeightSolver3D(WeightModel.FromMass(0.045), NamedProfiles.Get("paper"));
            HandPose Hand(double d, double t) => new HandPose(axis == 0 ? sign * d : 0, 1, axis == 2 ? sign * d : 0, true, true, t);
            solver.BeginHold(Hand(0, 0), axis == 0 ? sign * 99999 : 0, 1, axis == 2 ? sign * 99999 : 0);
            for (int i = 1; i <= 180; i++) solver.Step(Hand(Math.Min(1.0, i / 90.0), i / 90.0), 1 / 90.0);
            Assert.That(axis == 0 ? solver.ObjectX : solver.ObjectZ, Is.EqualTo(sign * WeightSolver.MaxCoordinate));
        }

        /// <summary>
        /// OPEN (reported, not fixed): issue 22's step rule (ALGORITHM.md §2: no frame's step beyond max(G, 1) × the hand's
        /// largest step within 100 ms + 1 cm) does not hold where the weight's map changes while the hand moves: §3 step 9
        /// counts an offset change of up to |Δhand| × |1 − G| as the hand's, in either direction, so such a change passes
        /// unglided and the object steps up to (2 − G) × the hand's step. Shrunk by FsCheck: 22.6 kg, faster-moves-further at
        /// sensitivity 2 (fastExponent 0.087, restBand 0.05) with experimental-blend, a 0.4 m lift in 0.378 s: a step of
        /// 81.7 mm where the hand's largest within 100 ms is 68.3 mm (seed 4); and 1000 kg with offset-relaxation (τ 0.01 s,
        /// stillFraction 2.7): 20.2 mm against 9.6 mm (seed 3).
        /// </summary>
        [Test, Explicit("open defect, reported: the glide's explained budget is blind to the direction of the change")]
        public void AMapThatChangesWhileTheHandMovesStepsNoFurtherThanTheStepRule()
        {
            var path = Simulation.HandPath.StartAt(0.8).Hold(0.5).MoveTo(1.2, 0.378).Hold(10.5);
            var frames = new Simulation.HeadsetSimulator { FrameRate = 90, PoseRate = 30, Latency = 0.045, JitterSd = 0.0015, LowConfidenceAboveSpeed = 0.6, LowConfidenceChance = 0.3, Seed = 1 }.Render(path);
            var profile = new WeightProfile("strong-pace", new WeightEffect[] { new FasterMovesFurther(0.08727519618542848, 1.5, 0.05, 0.16, 2), new ExperimentalBlend() });
            var solver = new WeightSolver(WeightModel.FromMass(22.645093056028553), profile);
            var y = Simulation.TraceReplay.Run(solver, frames);
            for (int i = 1; i < frames.Length; i++)
            {
                double near = 0;
                for (int j = 1; j < frames.Length; j++)
                    if (Math.Abs(frames[j].Time - frames[i].Time) <= 0.1 + 1e-9) near = Math.Max(near, Math.Abs(frames[j].HandY - frames[j - 1].HandY));
                Assert.That(Math.Abs(y[i] - y[i - 1]), Is.LessThanOrEqualTo(Math.Max(1, solver.Gain) * near + 0.01), "frame " + i);
            }
        }
    }
}
