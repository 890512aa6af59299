using System;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The reference lift the package states its numbers on (issue 31): the hand rests 0.3 s at 0.8 m, rises
    /// <see cref="Rise"/> = 0.2 m in a minimum-jerk motion of <see cref="DefaultSeconds"/> = 0.6 s (the calibration would
    /// measure it at 0.53 m/s, about the default v_std), and rests 0.5 s; 90 Hz frames with a new pose each, no latency,
    /// no jitter, so the numbers are the weight's alone. Through the solver (or <see cref="PaperLiteralSolver"/> for
    /// <c>paper-literal</c>): how far the object ends behind the hand, and the ratio of its rise to the hand's.
    /// </summary>
    public static class ReferenceLift
    {
        public const double Start = 0.8, Rise = 0.2, DefaultSeconds = 0.6, RestBefore = 0.3, RestAfter = 0.5, FrameRate = 90;

        /// <summary>The hand of a reference lift taking <paramref name="seconds"/> (finite, &gt; 0) to rise 0.2 m.</summary>
        public static TraceFrame[] Frames(double seconds = DefaultSeconds)
        {
            ConfigurationGuard.Positive(seconds, nameof(seconds));
            var path = HandPath.StartAt(Start).Hold(RestBefore).MoveTo(Start + Rise, seconds).Hold(RestAfter);
            return new HeadsetSimulator { FrameRate = FrameRate, PoseRate = FrameRate, Latency = 0, JitterSd = 0 }.Render(path);
        }

        /// <summary>Hand − object at the end of the lift, m (positive: behind), for an object of <paramref name="massKg"/> under
        /// <paramref name="profile"/>, a user of standard speed <paramref name="standardSpeed"/> and cue strength <paramref name="cueStrength"/>.</summary>
        public static double EndLag(WeightProfile profile, double massKg, double standardSpeed, double cueStrength = WeightSolver.DefaultCueStrength, double seconds = DefaultSeconds)
            => EndLag(profile, massKg, standardSpeed, cueStrength, Frames(seconds));

        /// <summary><see cref="EndLag(WeightProfile, double, double, double, double)"/> on frames made once by <see cref="Frames"/>.</summary>
        public static double EndLag(WeightProfile profile, double massKg, double standardSpeed, double cueStrength, TraceFrame[] frames)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            if (frames == null || frames.Length < 2) throw new ArgumentException("a lift needs frames", nameof(frames));
            double y;
            if (NamedProfiles.IsPaperLiteral(profile))
            {
                var literal = new PaperLiteralSolver(massKg) { CueStrength = cueStrength, MaxGain = profile.Limits.MaxGain };
                literal.BeginHold(frames[0].HandY, frames[0].HandY);
                for (int i = 1; i < frames.Length; i++) literal.Step(frames[i].HandY, frames[i].Tracked, frames[i].Time - frames[i - 1].Time);
                y = literal.ObjectY;
            }
            else
            {
                var solver = new WeightSolver(WeightModel.FromMass(massKg), profile, standardSpeed) { CueStrength = cueStrength };
                var heights = TraceReplay.Run(solver, frames);
                y = heights[heights.Length - 1];
            }
            return frames[frames.Length - 1].HandY - y;
        }

        /// <summary>
        /// The cue of the tuning model (<see cref="CueStrengthTuning"/>): ln(object's rise / hand's rise) at the end of the
        /// lift; 0 for the standard weight, negative for heavier objects, −∞ for an object that did not rise.
        /// </summary>
        public static double Cue(WeightProfile profile, double massKg, double standardSpeed, double cueStrength, TraceFrame[] frames)
        {
            double rise = Rise - EndLag(profile, massKg, standardSpeed, cueStrength, frames);
            return rise > 0 ? Math.Log(rise / Rise) : double.NegativeInfinity;
        }
    }
}
