using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// A bad setting fails when it is set, with a message that names the setting, says what it must be and shows the value
    /// given, round-trippable ("got 0.1" is the value, not a rounding of it): the four shapes of the core's messages.
    /// </summary>
    public class ConfigurationMessageTests
    {
        static string MessageOf(TestDelegate set) => Assert.Throws<ArgumentOutOfRangeException>(set).Message;

        [Test]
        public void APositiveSettingSaysSoAndShowsTheValue()
        {
            Assert.That(MessageOf(() => new HeadsetSimulator { FrameRate = -0.1 }), Does.StartWith("FrameRate must be a finite number greater than 0, got -0.1."));
            Assert.That(MessageOf(() => new HeadsetSimulator { PoseRate = double.NaN }), Does.StartWith("PoseRate must be a finite number greater than 0, got NaN."));
        }

        [Test]
        public void ANonNegativeSettingSaysSoAndShowsTheValue()
            => Assert.That(MessageOf(() => new HeadsetSimulator { Latency = -0.045 }), Does.StartWith("Latency must be a finite number of at least 0, got -0.045."));

        [Test]
        public void AFiniteSettingSaysSoAndShowsTheValue()
            => Assert.That(MessageOf(() => new HeadsetSimulator().Offset(1, 0.2, double.PositiveInfinity)), Does.StartWith("size must be a finite number, got ∞.").Or.StartWith("size must be a finite number, got Infinity."));

        [Test]
        public void ASettingWithARangeSaysTheRangeAndShowsTheValue()
        {
            var solver = new WeightSolver(WeightModel.FromMass(1));
            Assert.That(MessageOf(() => solver.CueStrength = 0.1),
                Does.StartWith("CueStrength must lie in [" + (1.0 / 3.0).ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ", 3], got 0.1."));
        }
    }
}
