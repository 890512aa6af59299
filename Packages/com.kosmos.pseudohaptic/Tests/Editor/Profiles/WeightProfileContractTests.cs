using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// What a scene or a researcher building a profile in code is told: a bad profile is refused naming what is wrong; the
    /// copies' names say what was added or taken out; a profile prints as its name and effect list; an unknown named
    /// profile is refused listing the known ones; the paper-literal profile lists the paper's effects.
    /// </summary>
    public class WeightProfileContractTests
    {
        [Test]
        public void ABadProfileIsRefusedNamingWhatIsWrong()
        {
            var e = Assert.Throws<ArgumentException>(() => new WeightProfile(" ", new WeightEffect[0]));
            Assert.That(e.ParamName, Is.EqualTo("name"));
            Assert.That(e.Message, Does.StartWith("name must not be empty."));
            Assert.That(Assert.Throws<ArgumentNullException>(() => new WeightProfile("p", null)).ParamName, Is.EqualTo("effects"));
            e = Assert.Throws<ArgumentException>(() => new WeightProfile("p", new WeightEffect[] { new WeightGain(), null }));
            Assert.That(e.ParamName, Is.EqualTo("effects"));
            Assert.That(e.Message, Does.StartWith("effects must not contain null."));
            e = Assert.Throws<ArgumentException>(() => new WeightProfile("p", new WeightEffect[] { new FloorClamp(), new WeightGain(), new FloorClamp(0.5) }));
            Assert.That(e.Message, Does.StartWith("effects lists floor-clamp twice."));
            Assert.That(Assert.Throws<ArgumentNullException>(() => NamedProfiles.Paper.With(null)).ParamName, Is.EqualTo("effect"));
        }

        [Test]
        public void ACopysNameSaysWhatWasAddedOrTakenOutUnlessOneIsGiven()
        {
            var gain = new WeightProfile("g", new WeightEffect[] { new WeightGain(), new FloorClamp() });
            Assert.That(gain.With(new SpeedCap()).Name, Is.EqualTo("g+speed-cap"));
            Assert.That(gain.Without<FloorClamp>().Name, Is.EqualTo("g-FloorClamp"));
            Assert.That(gain.Without<FloorClamp>("bare").Name, Is.EqualTo("bare"));
            Assert.That(gain.WithHandFilter(new OneEuroFilter()).Name, Is.EqualTo("g+" + new OneEuroFilter().Name));
            Assert.That(gain.WithHandFilter(null).Name, Is.EqualTo("g"), "no filter, nothing added");
            Assert.That(gain.WithHandFilter(new OneEuroFilter(), "smooth").Name, Is.EqualTo("smooth"));
        }

        [Test]
        public void AProfilePrintsAsItsNameAndItsEffectsInStageOrder()
            => Assert.That(new WeightProfile("g", new WeightEffect[] { new FloorClamp(), new WeightGain() }).ToString(), Is.EqualTo("g [weight-gain, floor-clamp]"));

        [Test]
        public void AnUnknownNamedProfileIsRefusedListingTheKnownOnes()
        {
            var e = Assert.Throws<ArgumentException>(() => NamedProfiles.Get("papr"));
            Assert.That(e.ParamName, Is.EqualTo("profile"));
            Assert.That(e.Message, Does.StartWith("profile 'papr' is unknown; known profiles: paper, paper-experiment, gain, xyz, paper-literal."));
        }

        [Test]
        public void ThePaperLiteralProfileListsThePapersEffectsAndItsOneSecondWindow()
        {
            var literal = NamedProfiles.PaperLiteral;
            Assert.That(literal.Has<WeightGain>() && literal.Has<ExperimentalBlend>() && literal.Has<FloorClamp>(), Is.True, "Eq. 4, Eq. 6 and the floor");
            Assert.That(literal.Effects.Count, Is.EqualTo(3));
            Assert.That(literal.Find<FloorClamp>().Floor, Is.EqualTo(0), "the floor at 0");
            Assert.That(literal.HandFilter, Is.InstanceOf<OneSecondAverage>(), "the paper's 1 s average");
        }
    }
}
