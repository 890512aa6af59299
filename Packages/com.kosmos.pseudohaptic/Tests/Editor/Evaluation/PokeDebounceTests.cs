using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>One poke is one answer: the fingertip's contacts as a 50 Hz physics step reports them.</summary>
    public class PokeDebounceTests
    {
        const double Step = 0.02;

        /// <summary>Reports a contact lasting from <paramref name="from"/> to <paramref name="to"/> as Unity would: an enter, then a stay each physics step.</summary>
        static bool Contact(PokeDebounce d, double from, double to)
        {
            bool poke = d.Touch(from);
            for (double t = from + Step; t <= to + 1e-9; t += Step) d.Stay(t);
            return poke;
        }

        [Test]
        public void AContactIsAPokeAndHoldingTheFingerInIsStillOne()
        {
            var d = new PokeDebounce();
            Assert.That(Contact(d, 1.0, 2.0), Is.True);
            Assert.That(d.Touch(2.0), Is.False, "a second enter while the finger rests in the button");
        }

        [Test]
        public void SlidingOntoTheNextButtonIsNotAPoke()
        {
            var d = new PokeDebounce();
            Assert.That(Contact(d, 1.0, 1.6), Is.True);
            Assert.That(Contact(d, 1.6, 1.9), Is.False, "the neighbour entered while the first is still touched");
            Assert.That(Contact(d, 1.92, 2.2), Is.False, "left the first a step ago");
        }

        [Test]
        public void FlickerAtAButtonsEdgeIsOnePoke()
        {
            var d = new PokeDebounce();
            int pokes = 0;
            for (int i = 0; i < 10; i++)
                if (Contact(d, 1.0 + i * 0.06, 1.0 + i * 0.06 + 0.02)) pokes++;
            Assert.That(pokes, Is.EqualTo(1));
        }

        [Test]
        public void WithdrawnAndPokedAgainIsTwoPokes()
        {
            var d = new PokeDebounce();
            Assert.That(Contact(d, 1.0, 1.3), Is.True);
            Assert.That(Contact(d, 1.8, 2.0), Is.True, "0.5 s out of contact");
        }

        [Test]
        public void TwoQuickPokesWithinTheCooldownAreOne()
        {
            var d = new PokeDebounce(cooldown: 0.5, releaseTime: 0.1);
            Assert.That(Contact(d, 1.0, 1.05), Is.True);
            Assert.That(Contact(d, 1.3, 1.35), Is.False, "a page changed under the finger 0.3 s ago");
            Assert.That(Contact(d, 1.7, 1.75), Is.True);
        }

        [Test]
        public void AContactWhoseEndIsNeverReportedStopsCounting()
        {
            var d = new PokeDebounce();
            Assert.That(Contact(d, 1.0, 1.2), Is.True);
            // The button was hidden at 1.2 while touched: no exit, no more stays.
            Assert.That(d.Touch(1.25), Is.False);
            Assert.That(d.Touch(1.9), Is.True);
        }

        [Test]
        public void APressNeedsOnlyTheCooldown()
        {
            var d = new PokeDebounce(cooldown: 0.4);
            Assert.That(d.Press(1.0), Is.True);
            Assert.That(d.Press(1.2), Is.False);
            Assert.That(d.Touch(1.3), Is.False, "one poke seen by both the fingertip and the Interaction SDK");
            Assert.That(d.Press(1.5), Is.True);
            d.Reset();
            Assert.That(d.Press(1.51), Is.True);
        }

        [Test]
        public void ExactlyTheReleaseTimeOutOfContactIsEnough()
        {
            // "touched no button for ReleaseTime": the fingertip last touched at 1.0, and 0.25 s later it is a new poke.
            var d = new PokeDebounce(cooldown: 0.5, releaseTime: 0.25);
            Assert.That(d.Touch(0.5), Is.True);
            d.Stay(1.0);
            Assert.That(d.Touch(1.25), Is.True);
        }

        [Test]
        public void ALastPokeExactlyTheCooldownOldIsOldEnough()
        {
            // "the last poke is at least Cooldown old": both by contact and by the Interaction SDK's press.
            var d = new PokeDebounce(cooldown: 0.5, releaseTime: 0.25);
            Assert.That(d.Touch(1.0), Is.True);
            Assert.That(d.Touch(1.5), Is.True);
            Assert.That(d.Press(2.0), Is.True);
            Assert.That(d.Press(2.5), Is.True);
        }

        [Test]
        public void AContactThatBeginsCountsAsTouchingEvenWithoutAStay()
        {
            // No cooldown: a second button entered 0.1 s after the first (a slide, with no stay reported between) is not a poke.
            var d = new PokeDebounce(cooldown: 0, releaseTime: 0.25);
            Assert.That(d.Touch(1.0), Is.True);
            Assert.That(d.Touch(1.1), Is.False);
            Assert.That(d.Touch(1.2), Is.False, "0.1 s after the last contact began");
            Assert.That(d.Touch(1.5), Is.True, "0.3 s out of contact");
        }

        [Test]
        public void ZeroTimesAreAllowedAndMeanNoWait()
        {
            var d = new PokeDebounce(0, 0);
            Assert.That((d.Cooldown, d.ReleaseTime), Is.EqualTo((0.0, 0.0)));
            Assert.That(d.Touch(1.0), Is.True);
            Assert.That(d.Touch(1.02), Is.True);
            Assert.That(d.Press(1.02), Is.True);
        }

        [Test]
        public void ABadSettingIsRefusedNamingItAndWhatItMustBe()
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new PokeDebounce(-0.1, 0.1));
            Assert.That(e.ParamName, Is.EqualTo("cooldown"));
            Assert.That(e.Message, Does.Contain("finite number ≥ 0"));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => new PokeDebounce(0.5, -0.1));
            Assert.That(e.ParamName, Is.EqualTo("releaseTime"));
            Assert.That(e.Message, Does.Contain("finite number ≥ 0"));
        }

        [TestCase(-0.1, 0.1)]
        [TestCase(0.5, double.NaN)]
        [TestCase(double.PositiveInfinity, 0.1)]
        public void SettingsMustBeFiniteAndNotNegative(double cooldown, double release)
        {
            Assert.Throws<ArgumentOutOfRangeException>(() => new PokeDebounce(cooldown, release));
        }
    }
}
