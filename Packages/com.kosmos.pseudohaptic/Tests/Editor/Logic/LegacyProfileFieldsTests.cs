using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>An old (pre-issue-33) profile asset's fields as the effect list receives them (<see cref="LegacyProfileFields"/>).</summary>
    public sealed class LegacyProfileFieldsTests
    {
        [Test]
        public void AnOnOffSettingThatWasOffStaysOff([Values(false, true)] bool requireHighConfidence)
        {
            var old = new LegacyProfileFields { trackingLossHold = true, settleTime = 0.2f, requireHighConfidence = requireHighConfidence };
            WeightProfile p = ProfileEffectList.Build("old", old.Effects(), SolverLimits.Default);
            Assert.That(p.Find<TrackingLossHold>().RequireHighConfidence, Is.EqualTo(requireHighConfidence));
        }

        [Test]
        public void EachOfTheOldLimitsArrivesUnderItsOwnName()
        {
            // Values away from the defaults, so that a limit lost on the way would show.
            var old = new LegacyProfileFields { maxGain = 2.5f, maxHandSpeed = 7.5f, maxFrameTime = 0.05f, glideSpeed = 0.5f };
            SolverLimits limits = ProfileEffectList.Limits(old.Limits());
            Assert.That(limits.MaxGain, Is.EqualTo(2.5));
            Assert.That(limits.MaxHandSpeed, Is.EqualTo(7.5));
            Assert.That(limits.MaxFrameTime, Is.EqualTo((double)0.05f));
            Assert.That(limits.GlideSpeed, Is.EqualTo(0.5));
        }
    }
}
