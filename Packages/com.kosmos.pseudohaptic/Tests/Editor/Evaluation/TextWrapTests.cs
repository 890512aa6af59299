using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    public class TextWrapTests
    {
        [Test]
        public void BreaksAtSpacesWithinTheWidth()
        {
            string text = "Watching an object as I lifted it told me how heavy it was.";
            string wrapped = TextWrap.Wrap(text, 20);
            Assert.That(wrapped, Is.EqualTo("Watching an object\nas I lifted it told\nme how heavy it was."));
            foreach (string line in wrapped.Split('\n')) Assert.That(line.Length, Is.LessThanOrEqualTo(20));
            Assert.That(wrapped.Replace('\n', ' '), Is.EqualTo(text));
        }

        [Test]
        public void KeepsLineBreaksCutsLongWordsDropsExtraSpaces()
        {
            Assert.That(TextWrap.Wrap("a  b\r\nc", 10), Is.EqualTo("a b\nc"));
            Assert.That(TextWrap.Wrap("abcdefghij xy", 4), Is.EqualTo("abcd\nefgh\nij\nxy"));
            Assert.That(TextWrap.Wrap("abcd", 4), Is.EqualTo("abcd"));
            Assert.That(TextWrap.Wrap("", 4), Is.EqualTo(""));
            Assert.That(TextWrap.Wrap(null, 4), Is.EqualTo(""));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => TextWrap.Wrap("a", 0));
            Assert.That(e.ParamName, Is.EqualTo("maxChars"));
            Assert.That(e.Message, Is.Not.EqualTo(new ArgumentException("", e.ParamName).Message), "says what a line must hold");
        }

        [Test]
        public void ALineOfOneCharacterHoldsOneCharacter()
        {
            Assert.That(TextWrap.Wrap("ab c", 1), Is.EqualTo("a\nb\nc"));
        }
    }
}
