using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The end of the solver's frame (ALGORITHM.md §3, steps 3–11) at its edges, driven as a headset drives it: 30 Hz poses
    /// 45 ms late over 90 or 120 Hz frames, 1 mm jitter, losses, a garbage pose, a glitched grab, a change of mass or profile
    /// mid-hold. Each test states what the user sees (where the object is,
    /// that it does not step, creep or flip to the wrong side of the hand), or pins a field of
    /// <see cref="MotionFrame"/> or <see cref="HoldState"/> that a scene's own effect reads.
    /// </summary>
    public class PipelineEdgeTests
    {
        /// <summary>The glide speed ALGORITHM.md states (§3 step 9, §5): 0.3 m/s.</summary>
        const double DocumentedGlideSpeed = 0.3;

        static WeightProfile Only(params WeightEffect[] effects) => new WeightProfile("test", effects);

        /// <summary>Quest-like poses: the hand at pose time t is <see cref="Hand"/>(t) plus jitter; a frame at render time T
        /// shows the newest pose taken at or before T − latency.</summary>
        sealed class Quest
        {
            public readonly WeightSolver Solver;
            public double FrameRate = 90, PoseRate = 30, Latency = 0.045, Jitter = 0.001;
            public Func<double, double> Hand = t => 1.0;
            public bool Tracked = true;
            public double Time;
            public double LastY = double.NaN, PrevPoseY = double.NaN;
            public bool NewPose;
            double _lastPoseTime = double.NaN;
            public readonly List<double> Objects = new List<double>();

            public Quest(WeightSolver solver) { Solver = solver; }

            static double Noise(int k)
            {
                double x = Math.Sin(k * 12.9898 + 78.233) * 43758.5453;
                return 2 * (x - Math.Floor(x)) - 1;
            }

            public double Dt => 1 / FrameRate;

            /// <summary>The pose the headset shows at render time <paramref name="time"/>: (height, pose time).</summary>
            public (double Y, double T) PoseAt(double time)
            {
                int k = (int)Math.Floor((time - Latency) * PoseRate);
                double pt = k / PoseRate;
                return (Hand(pt) + Jitter * Noise(k), pt);
            }

            public double Frame()
            {
                Time += Dt;
                var (y, pt) = PoseAt(Time);
                NewPose = Tracked && !(pt == _lastPoseTime);
                HandSample sample;
                if (Tracked)
                {
                    if (NewPose) { PrevPoseY = LastY; _lastPoseTime = pt; }
                    LastY = y;
                    sample = new HandSample(y, true, true, pt);
                }
                else sample = HandSample.Lost;
                double o = Solver.Step(sample, Dt);
                Objects.Add(o);
                return o;
            }

            public void Run(double seconds) { for (int n = (int)Math.Round(seconds * FrameRate); n > 0; n--) Frame(); }
        }

        /// <summary>Records the frame as the hand-motion stage sees it (after the estimator and the hand filter).</summary>
        sealed class HandProbe : WeightEffect
        {
            public readonly List<MotionFrame> Frames = new List<MotionFrame>();
            public override string Name => "hand-probe";
            public override EffectStage Stage => EffectStage.HandMotion;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => Frames.Add(frame);
        }

        // ---- a hold begun untracked (ALGORITHM.md §6, §5: the workspace is where its first pose came) ----

        [Test]
        public void AHoldBegunUntrackedJudgesGarbagePosesAgainstTheWorkspaceOfItsFirstPose()
        {
            var s = Run.Solver(0.5);
            s.BeginHold(double.NaN, 0.9);
            var q = new Quest(s) { Tracked = false };
            q.Run(0.2);
            q.Tracked = true;
            q.Run(0.5);                    // the first pose anchors the hold at 1.0 m; the hand rests there
            q.Tracked = false;
            q.Run(5);                      // lost for 5 s: 10 m/s could reach 50 m
            double before = s.ObjectY;
            q.Tracked = true;
            q.Hand = t => 31.0;            // a pose 30 m from where the hold began, reported tracked: no hand's
            q.Jitter = 0;
            for (int i = 0; i < 10; i++)
                Assert.That(q.Frame(), Is.EqualTo(before), "frame " + i + ": a pose 30 m away moved the object");
        }

        // ---- the hand filter's frame (MotionFrame.HandFiltered, HandBefore/After/Delta: public to a scene's effects) ----

        [Test]
        public void WithAHandFilterEffectsSeeTheFilteredHandItsStepAndThatItIsFiltered()
        {
            var probe = new HandProbe();
            var s = Run.Solver(0.09, Only(new WeightGain(), probe).WithHandFilter(new ExponentialSmoothing(0.05)));
            s.BeginHold(1.0, 0.95);
            var q = new Quest(s) { Hand = t => t < 0.3 ? 1.0 : Math.Min(1.3, 1.0 + (t - 0.3)) };
            q.Run(0.4);
            q.Tracked = false;
            q.Run(0.2);
            q.Tracked = true;
            q.Run(0.6);
            Assert.That(probe.Frames.Count, Is.GreaterThan(100));
            double before = 1.0;
            foreach (var f in probe.Frames)
            {
                Assert.That(f.HandFiltered, Is.True, "a filtered hand is marked filtered");
                Assert.That(f.HandBefore, Is.EqualTo(before), "the step starts where the last frame's hand ended");
                Assert.That(f.HandDelta, Is.EqualTo(f.HandAfter - f.HandBefore), "HandDelta is the filtered hand's step");
                Assert.That(Math.Abs(f.HandDelta), Is.LessThan(0.05), "a 1 m/s hand, smoothed, steps less than 5 cm a frame");
                before = f.HandAfter;
            }
        }

        // ---- a scene's own effect writing an absurd offset (ALGORITHM.md §3 step 11: the finite guard) ----

        /// <summary>A scene's object-motion effect that writes <see cref="Value"/> as the offset on frames [From, To).</summary>
        sealed class AbsurdOffset : WeightEffect
        {
            public double Value;
            public int From, To, Frame;
            public override string Name => "absurd-offset";
            public override EffectStage Stage => EffectStage.ObjectMotion;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
            {
                if (Frame >= From && Frame < To) frame.Offset = Value;
                Frame++;
            }
        }

        [Test]
        public void AnEffectsAbsurdOffsetNeverReachesTheTransformAndTheFramesAfterItAreTheCleanRunsFrames(
            [Values(1.7e308, -1.7e308, 1e6, double.PositiveInfinity, double.NaN)] double value,
            [Values(1, 2)] int frames, [Values(false, true)] bool corrected)
        {
            // 90 g lifted 0.3 m in 1 s on Quest-like poses; the scene's effect comes after the offset correction.
            WeightEffect[] effects = corrected
                ? new WeightEffect[] { new WeightGain(), new OffsetCorrection() }
                : new WeightEffect[] { new WeightGain() };
            double[] Run(AbsurdOffset absurd)
            {
                var list = new List<WeightEffect>(effects) { absurd };
                var s = new WeightSolver(WeightModel.FromMass(0.09), new WeightProfile("scene", list.ToArray()));
                s.BeginHold(0.8, 0.8);
                var q = new Quest(s) { Hand = t => 0.8 + 0.3 * Math.Min(1, Math.Max(0, t - 0.2)) };
                q.Run(2);
                return q.Objects.ToArray();
            }
            var clean = Run(new AbsurdOffset { From = -1, To = -1 });
            var glitched = Run(new AbsurdOffset { Value = value, From = 60, To = 60 + frames });
            double ceiling = new OffsetCorrection().Ceiling;
            for (int i = 0; i < glitched.Length; i++)
            {
                Assert.That(float.IsFinite((float)glitched[i]), Is.True, "frame " + i + ": a float transform holds it");
                if (i >= 60 && i < 60 + frames)
                {
                    // The frame itself: the object stays where it was, or (under the correction) is held within its ceiling of the hand.
                    if (corrected) Assert.That(Math.Abs(glitched[i] - glitched[i - 1]), Is.LessThanOrEqualTo(ceiling + 0.01), "frame " + i);
                    else Assert.That(glitched[i], Is.EqualTo(glitched[i - 1]), "frame " + i + ": where it was");
                }
                else Assert.That(glitched[i], Is.EqualTo(clean[i]), "frame " + i + ": the clean run's");
            }
        }

        // ---- the offsets the hold state gives (a scene's effect and the recorder read them) ----

        [Test]
        public void TheHoldStatesOffsetsAreTheHandLessTheObjectAndTheHandLessTheHeldPoint()
        {
            var s = Run.Solver(2);
            s.BeginHold(1.0, 0.9, 0.0); // grabbed 10 cm above the pivot
            var q = new Quest(s) { Hand = t => 1.0 + 0.3 * Math.Min(1, t), Jitter = 0, Time = 0.045 };
            q.Run(1.5);
            var state = s.State;
            Assert.That(state.Offset, Is.EqualTo(state.HandY - state.ObjectY), "hand − object");
            Assert.That(state.Offset, Is.GreaterThan(0.2), "a 2 kg object hangs below: the 10 cm grab and part of the 0.3 m lift");
            Assert.That(state.RelativeOffset, Is.EqualTo(state.HandY - state.HeldY), "hand − held point");
            Assert.That(state.RelativeOffset, Is.EqualTo(state.Offset - 0.1).Within(1e-12), "the grab's 10 cm taken out");
        }

        // ---- the pose count a scene's effect reads (HoldState.PoseCount: up to three, from 0 again after a loss) ----

        [Test]
        public void ThePoseCountRisesToThreeAndStaysThereAndALossStartsItAgain()
        {
            var s = Run.Solver(0.5);
            var q = new Quest(s) { Hand = t => 1.0 + 0.1 * t, Time = 0.045 + 1.0 / 30 - 1.0 / 90 }; // the first frame shows the pose after the grab's
            s.BeginHold(1.0, 1.0, 0.0);
            Assert.That(s.State.PoseCount, Is.EqualTo(1), "the grab's pose");
            var seen = new List<int>();
            while (seen.Count < 12) { q.Frame(); if (q.NewPose) seen.Add(s.State.PoseCount); }
            Assert.That(seen.GetRange(0, 2), Is.EqualTo(new[] { 2, 3 }));
            Assert.That(seen.GetRange(2, 10), Is.All.EqualTo(3), "counted up to three, not beyond");
            q.Tracked = false;
            q.Run(0.5);
            q.Tracked = true;
            while (!q.NewPose) q.Frame();
            Assert.That(s.State.PoseCount, Is.LessThan(3), "tracking came back: the count starts again");
        }

        // ---- the offset ceiling, the negative side (a light object leads by at most the ceiling) ----

        [Test]
        public void ALightObjectLeadingFarWhenTheCorrectionComesInStaysAboveTheHandWithinTheCeiling()
        {
            var correction = new OffsetCorrection();
            var without = Only(new WeightGain());
            var with = Only(new WeightGain(), correction);
            var model = WeightModel.FromMass(0.015);              // 15 g: G = 3, a lead of 2 × the lift
            var s = new WeightSolver(model, without);
            s.BeginHold(0.8, 0.8);
            var q = new Quest(s) { Hand = t => t < 0.3 ? 0.8 : Math.Min(1.1, 0.8 + (t - 0.3) * 0.5) };
            q.Run(1.4);
            Assert.That(s.ObjectY - q.LastY, Is.GreaterThan(0.5), "without the correction the 15 g object leads by 0.6 m");
            s.Configure(model, with, s.StandardSpeed);            // the scene turns the offset correction on mid-hold
            for (int i = 0; i < 200; i++)
            {
                double o = q.Frame();
                Assert.That(o - q.LastY, Is.GreaterThanOrEqualTo(0), "frame " + i + ": the light object shows below the hand");
                Assert.That(o - q.LastY, Is.LessThanOrEqualTo(correction.Ceiling), "frame " + i + ": beyond the ceiling");
            }
        }

        // ---- a glitched grab (ALGORITHM.md §2: the base, and the hold's start, are read on the median) ----

        [Test]
        public void AGrabOnAGlitchedPoseStartsTheHoldWhereTheHandReallyWas()
        {
            var s = Run.Solver(0.5);
            s.BeginHold(1.03, 0.98, 0.0);                         // the grab's own pose 3 cm high: a glitch
            var q = new Quest(s) { Hand = t => 1.0, Jitter = 0, Time = 0.045 + 1.0 / 30 - 0.005 };
            while (s.State.AnchorPending) q.Frame();              // two more poses: the median of three is 1.0
            Assert.That(s.State.Base, Is.EqualTo(1.0).Within(1e-12), "the lift is measured from the median");
            Assert.That(s.State.StartY, Is.EqualTo(1.0).Within(1e-12), "the hold starts where the hand really was");
        }

        // ---- the glide's slope where the height deceleration shapes the carried lift ----

        [Test]
        public void UnderHeightDecelerationAFastLiftGlidesNothingTheObjectMovesOnlyWithNewPoses()
        {
            var s = Run.Solver(0.09, Only(new WeightGain(), new HeightDeceleration()));   // G = 0.5
            s.BeginHold(0.8, 0.75);
            var q = new Quest(s) { FrameRate = 120, Hand = t => t < 0.3 ? 0.8 : Math.Min(1.4, 0.8 + (t - 0.3) * 2.5) };
            double last = s.ObjectY;
            for (int i = 0; i < 200; i++)
            {
                double o = q.Frame();
                if (!q.NewPose)
                    Assert.That(o, Is.EqualTo(last), "frame " + i + ": the object moved on a frame the hand did not");
                last = o;
            }
            Assert.That(q.LastY - s.ObjectY, Is.GreaterThan(0.2), "the 0.6 m lift leaves the object hanging below");
        }

        [Test]
        public void UnderHeightDecelerationAMassThatGrowsMidLiftNeverDropsTheObjectFasterThanItGlides()
        {
            var profile = Only(new WeightGain(), new HeightDeceleration());
            var s = Run.Solver(0.09, profile);                                            // G = 0.5
            s.BeginHold(0.8, 0.75);
            var q = new Quest(s) { FrameRate = 90, Hand = t => t < 0.3 ? 0.8 : Math.Min(1.4, 0.8 + (t - 0.3) * 2.0) };
            double last = s.ObjectY;
            q.LastY = 0.8;
            bool changed = false;
            for (int i = 0; i < 120; i++)
            {
                if (!changed && q.Time > 0.5 && q.PoseAt(q.Time + q.Dt).T != q.PoseAt(q.Time).T)
                {
                    s.Configure(WeightModel.FromMass(0.3), profile, s.StandardSpeed);   // G = 0.15 on a frame the hand rises
                    changed = true;
                }
                double handBefore = q.LastY, o = q.Frame();
                if (q.LastY >= handBefore)
                    Assert.That(o - last, Is.GreaterThanOrEqualTo(-DocumentedGlideSpeed * q.Dt - 1e-9),
                        "frame " + i + ": the object dropped faster than a change of mass glides while the hand rose");
                last = o;
            }
            Assert.That(changed, Is.True);
            Assert.That(s.Gain, Is.EqualTo(0.15).Within(1e-9));
        }

        // ---- across a gap: the object goes no further than the hand went; a change of mass glides ----

        /// <summary>A hold lifted to <paramref name="lift"/>, lost for 0.3 s while the hand moves by <paramref name="handStep"/>,
        /// and made of <paramref name="massAfter"/> on the frame it comes back. Returns (hand step, object step) of that frame.</summary>
        static (double Hand, double Object, double Dt) ChangeOfMassAcrossAGap(double massBefore, double massAfter, double lift, double handStep, double maxGain)
        {
            var profile = new WeightProfile("test", new WeightEffect[] { new WeightGain() }, new SolverLimits(maxGain: maxGain));
            var s = Run.Solver(massBefore, profile);
            s.BeginHold(1.0, 1.0);
            double top = 1.0 + lift;
            var q = new Quest(s) { Hand = t => t < 0.3 ? 1.0 : Math.Min(top, 1.0 + (t - 0.3) * 0.5) };
            q.Run(0.3 + lift / 0.5 + 0.5);
            q.Tracked = false;
            q.Hand = t => top + handStep;
            q.Run(0.3);
            double handBefore = q.LastY, objectBefore = s.ObjectY;
            s.Configure(WeightModel.FromMass(massAfter), profile, s.StandardSpeed);
            q.Tracked = true;
            double o = q.Frame();
            Assert.That(q.NewPose, Is.True);
            return (q.LastY - handBefore, o - objectBefore, q.Dt);
        }

        [TestCase(0.009, 0.01125, 0.01, TestName = "ALightObjectMadeHeavierAsTheHandComesBackHigherGoesNoFurtherThanTheHand")]
        [TestCase(0.01125, 0.009, -0.01, TestName = "ALightObjectMadeLighterAsTheHandComesBackLowerGoesNoFurtherThanTheHand")]
        public void AChangeOfMassAcrossAGapWithALargeGainMovesTheObjectNoFurtherThanTheHand(double before, double after, double handStep)
        {
            // maxGain 10: G = 5 and 4 (0.045 kg / m), a light object's lead of 3–4 × the lift.
            var (hand, obj, dt) = ChangeOfMassAcrossAGap(before, after, 0.1, handStep, 10);
            Assert.That(Math.Abs(hand - handStep), Is.LessThan(0.003));
            Assert.That(Math.Abs(obj), Is.LessThanOrEqualTo(Math.Abs(hand) + DocumentedGlideSpeed * dt + 1e-9),
                "the object stepped " + obj + " m where the hand stepped " + hand + " m");
        }

        [Test]
        public void AHeavyObjectMadeTheStandardWeightAsTheHandComesBackLowerStepsWithTheHandAndGlides()
        {
            var (hand, obj, dt) = ChangeOfMassAcrossAGap(0.09, PhysicalConstants.StandardMassKg, 0.3, -0.1, 3);
            Assert.That(Math.Abs(hand + 0.1), Is.LessThan(0.003));
            Assert.That(Math.Abs(obj - hand), Is.LessThanOrEqualTo(DocumentedGlideSpeed * dt + 1e-9),
                "the object stepped " + obj + " m where the hand stepped " + hand + " m: the change of mass did not glide");
        }
    
        // ---- the bounds ALGORITHM.md writes, at the bound itself ----

        /// <summary>A scene's position effect that puts the object at <see cref="At"/> on the frame numbered <see cref="On"/>.</summary>
        sealed class PlaceAt : WeightEffect
        {
            public double At;
            public int On, Frame;
            public override string Name => "place-at";
            public override EffectStage Stage => EffectStage.Position;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
            {
                if (Frame++ == On) frame.NewObjectY = At;
            }
        }

        [TestCase(1e5, true)]
        [TestCase(-1e5, true)]
        [TestCase(100000.00000000001, false)]
        [TestCase(-100000.00000000001, false)]
        public void AHeightOfExactly1E5IsAHeightAndOneBeyondItIsNot(double at, bool taken)
        {
            // ALGORITHM.md §3 step 11: a height that "lies beyond ±10⁵ m" is refused; ±10⁵ m itself is a height.
            var s = new WeightSolver(WeightModel.FromMass(0.045), new WeightProfile("scene", new WeightEffect[] { new PlaceAt { At = at, On = 3 } }));
            s.BeginHold(1.0, 1.0, 0);
            double before = double.NaN;
            for (int i = 1; i <= 4; i++)
            {
                before = s.ObjectY;
                s.Step(new HandSample(1.0 + 0.01 * i, true, true, i / 30.0), 1 / 30.0);
            }
            Assert.That(s.ObjectY, Is.EqualTo(taken ? at : before));
        }

        [TestCase(1)]
        [TestCase(-1)]
        public void APoseExactlyTheWorkspaceRadiusAwayIsTrackedAndOneBeyondItIsNot(int direction)
        {
            // ALGORITHM.md §5: a pose *farther* than the workspace radius from where the hold began is not tracked. With the
            // smallest radius, 1 m, the hand walks 1/32 m a pose (under 1 m/s) from 1 m to exactly 2 m (or 0 m), then one step
            // beyond: the golf ball (no effect, gain 1) is at the hand up to the radius and stays there after it.
            var s = new WeightSolver(WeightModel.FromMass(PhysicalConstants.StandardMassKg), Only().WithLimits(new SolverLimits(workspaceRadius: 1.0)));
            s.BeginHold(1.0, 1.0, 0);
            for (int i = 1; i <= 33; i++)
            {
                double hand = 1.0 + direction * i / 32.0;
                s.Step(new HandSample(hand, true, true, i / 30.0), 1 / 30.0);
                Assert.That(s.ObjectY, Is.EqualTo(i <= 32 ? hand : 1.0 + direction), "pose " + i);
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void AGlideOfExactly1E5IsAGlideAndOneBeyondItIsNot(bool beyond)
        {
            // ALGORITHM.md §3 step 9: an offset change the hand's motion does not explain glides away, but a glide beyond ±10⁵ m
            // (an absurd offset a scene's effect wrote) is none. A gain of 1 explains no change; a glide speed of 0.25 m/s over
            // frames of 1/64 s takes steps of 1/256 m, so a change of 10⁵ + 1/256 m leaves a glide of exactly −10⁵ m after
            // the frame's step (every number exact in binary): the object moves by that one step. At the next double beyond,
            // there is no glide and the object goes where the offset puts it.
            const double dt = 1 / 64.0, step = 1 / 256.0;
            // The next double up, from its bits (Math.BitIncrement is not in Unity's .NET profile).
            double change = beyond ? BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(1e5 + step) + 1) : 1e5 + step;
            var profile = Only(new AbsurdOffset { Value = change, From = 3, To = 4 }).WithLimits(new SolverLimits(glideSpeed: 0.25));
            var s = new WeightSolver(WeightModel.FromMass(PhysicalConstants.StandardMassKg), profile);
            s.BeginHold(1.0, 1.0, 0);
            double hand = 1.0;
            for (int i = 1; i <= 4; i++)
            {
                hand = 1.0 + i / 128.0;
                s.Step(new HandSample(hand, true, true, i * dt), dt);
            }
            Assert.That(s.State.Glide, Is.EqualTo(beyond ? 0 : -1e5));
            Assert.That(s.ObjectY, Is.EqualTo(beyond ? hand - change : hand - step));
        }

        [TestCase(0.005, 0.0)]
        [TestCase(0.00500001, 0.00500001)]
        [TestCase(-0.005, 0.0)]
        [TestCase(-0.00500001, -0.00500001)]
        public void TheLiftIsMeasuredFromTheMedianOnlyWhenTheGrabsPoseLiesMoreThan5MmFromIt(double later, double startShift)
        {
            // ALGORITHM.md: the grab's pose is taken for a glitch when it lies *more than* 5 mm from the median of the first
            // three poses; at exactly 5 mm it is the hand's own pose (the heights are exact in binary: 0 and ±0.005).
            var s = new WeightSolver(WeightModel.FromMass(0.5), NamedProfiles.Paper);
            s.BeginHold(0.0, 0.0, 0);
            for (int i = 1; i <= 2; i++) s.Step(new HandSample(later, true, true, i / 30.0), 1 / 30.0);
            Assert.That(s.State.StartY, Is.EqualTo(startShift));
        }
}
}
