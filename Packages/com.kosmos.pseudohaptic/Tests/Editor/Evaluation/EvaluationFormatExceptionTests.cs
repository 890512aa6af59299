using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>The one-line "source:line: reason" a study designer reads when a file cannot be used.</summary>
    public class EvaluationFormatExceptionTests
    {
        [Test]
        public void ReadsAsSourceLineReasonAndKeepsEachPart()
        {
            var e = new EvaluationFormatException("R.csv", 4, "response 6 is outside the scale 1 to 5");
            Assert.That(e.Message, Is.EqualTo("R.csv:4: response 6 is outside the scale 1 to 5"));
            Assert.That(e.SourceName, Is.EqualTo("R.csv"));
            Assert.That(e.Line, Is.EqualTo(4));
            Assert.That(e.Reason, Is.EqualTo("response 6 is outside the scale 1 to 5"));
        }

        [Test]
        public void AFaultOfTheWholeFileNamesNoLine()
        {
            Assert.That(new EvaluationFormatException("questionnaires", 0, "no definitions").Message, Is.EqualTo("questionnaires: no definitions"));
        }

        [Test]
        public void AnUnnamedSourceStillReadsAsSourceLineReason()
        {
            var e = new EvaluationFormatException(null, 3, null);
            Assert.That(e.SourceName, Is.EqualTo(""));
            Assert.That(e.Reason, Is.EqualTo(""));
            Assert.That(e.Message, Does.EndWith(":3: "));
            Assert.That(e.Message, Does.Not.StartWith(":"), "a placeholder stands for the unnamed source");
            Assert.That(new EvaluationFormatException("", 3, "x").Message, Does.Not.StartWith(":"));
        }

        [TestCase("participant 'P1\nP2' is unknown")]
        [TestCase("participant 'P1\rP2' is unknown")]
        public void ALineBreakInTheReasonBecomesASpaceSoTheMessageIsOneLine(string reason)
        {
            Assert.That(new EvaluationFormatException("R.csv", 2, reason).Message, Is.EqualTo("R.csv:2: participant 'P1 P2' is unknown"));
        }
    }
}
