using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// A CSV file with a header naming its columns (evaluation.md §4): columns by name, optional columns, the
    /// limits a caller sets on rows and characters, the messages a study designer reads, and Escape.
    /// </summary>
    public class CsvTableTests
    {
        static readonly string[] Answer = { "participant", "questionnaire", "item", "response" };

        sealed class WatchedReader : StringReader
        {
            public bool Disposed;
            public WatchedReader(string text) : base(text) { }
            protected override void Dispose(bool disposing)
            {
                Disposed = true;
                base.Dispose(disposing);
            }
        }

        static List<CsvTable.Row> Rows(string text, int maxRows, long maxCharacters, params string[] columns)
            => new List<CsvTable.Row>(CsvTable.Stream(new StringReader(text), "R.csv", maxRows, maxCharacters, columns));

        static void SaysWhy(ArgumentException e)
            => Assert.That(e.Message, Is.Not.EqualTo(new ArgumentException("", e.ParamName).Message), "the message says what is wrong, not only which argument");

        [Test]
        public void AMissingColumnNamesItTheHeaderToWriteAndTheHeaderFound()
        {
            var e = Assert.Throws<EvaluationFormatException>(() => CsvTable.Parse("participant,questionnaire,item\nP1,immersion,1\n", "R.csv", Answer));
            // evaluation.md §4: `R.csv:1: missing column 'response': the header must name participant,questionnaire,item,response (found …)`
            Assert.That(e.Message, Is.EqualTo("R.csv:1: missing column 'response': the header must name participant,questionnaire,item,response (found participant,questionnaire,item)"));
        }

        [Test]
        public void AnEmptyFileSaysWhichHeaderItNeeds()
        {
            var e = Assert.Throws<EvaluationFormatException>(() => CsvTable.Parse("\n", "R.csv", Answer));
            Assert.That(e.Line, Is.EqualTo(1));
            Assert.That(e.Reason, Does.Contain("participant,questionnaire,item,response"));
        }

        [Test]
        public void AVeryLongHeaderIsShownCutAndMarkedCutInTheOneLineMessage()
        {
            var names = new string[300];
            for (int i = 0; i < names.Length; i++) names[i] = "column" + i.ToString("000", System.Globalization.CultureInfo.InvariantCulture);
            string header = string.Join(",", names);
            var e = Assert.Throws<EvaluationFormatException>(() => CsvTable.Parse(header + "\n", "R.csv", Answer));
            Assert.That(e.Message.Length, Is.LessThan(header.Length / 4), "a 3,000-character header is not copied whole");
            Assert.That(e.Message, Does.Contain("(found column000,column001,"));
            Assert.That(e.Message, Does.Contain("…"), "the cut is marked");
        }

        // The cut mark says something was cut: a header of 80 characters is shown whole and unmarked, one of 81 is
        // shown as its first 80 and the mark.
        [TestCase(80, false)]
        [TestCase(81, true)]
        public void OnlyAHeaderLongerThanEightyCharactersIsShownCutAndMarkedCut(int length, bool cut)
        {
            string header = "note" + new string('0', length - 4);
            var e = Assert.Throws<EvaluationFormatException>(() => CsvTable.Parse(header + "\n", "R.csv", Answer));
            string shown = cut ? header.Substring(0, 80) + "…" : header;
            Assert.That(e.Message, Does.EndWith("(found " + shown + ")"));
        }

        [Test]
        public void OptionalColumnsAreFoundWhereverTheyStandAndAnAbsentOneReadsNull()
        {
            var present = new bool[2];
            var rows = new List<CsvTable.Row>(CsvTable.Stream(new StringReader("condition,Participant,item,response,questionnaire\nvisual,P1,3,4,immersion\n"),
                "R.csv", 10, 1000, Answer, new[] { "condition", "note" }, present));
            Assert.That(present, Is.EqualTo(new[] { true, false }));
            Assert.That(rows.Count, Is.EqualTo(1));
            var r = rows[0];
            Assert.That(new[] { r[0], r[1], r[2], r[3], r[4], r[5] }, Is.EqualTo(new[] { "P1", "immersion", "3", "4", "visual", null }));
        }

        [Test]
        public void TheRowLimitAllowsExactlyThatManyRowsAndNamesTheLineOfTheFirstBeyond()
        {
            Assert.That(Rows("a\n", 0, 0, "a"), Is.Empty, "a header-only file under limits of 0");
            Assert.That(Rows("a\n1\n\n2\n", 2, 1000, "a").Count, Is.EqualTo(2));
            var e = Assert.Throws<EvaluationFormatException>(() => Rows("a\n1\n\n2\n3\n", 2, 1000, "a"));
            Assert.That(e.Line, Is.EqualTo(5));
            Assert.That(e.Reason, Does.Contain("more than 2 rows"));
        }

        [Test]
        public void TheCharacterLimitCountsTheRequestedFieldsAndNamesTheLineThatPassesIt()
        {
            // Requested: a and b (5 characters a row); c is not kept and not counted.
            Assert.That(Rows("a,b,c\n12,345,xxxxxxxx\n1,2345,\n", 10, 10, "a", "b").Count, Is.EqualTo(2));
            var e = Assert.Throws<EvaluationFormatException>(() => Rows("a,b,c\n12,345,x\n1,2345,x\n1,2,x\n", 10, 10, "a", "b"));
            Assert.That(e.Line, Is.EqualTo(4));
            Assert.That(e.Reason, Does.Contain("more than 10 characters"));
        }

        [Test]
        public void ArgumentsAreCheckedWhenCalledBeforeAnyRowIsAskedFor()
        {
            var reader = new StringReader("a\n1\n");
            var none = new string[0];
            Assert.That(Assert.Throws<ArgumentNullException>(() => CsvTable.Parse(null, "R.csv", "a")).ParamName, Is.EqualTo("text"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => CsvTable.Stream(null, "R.csv", 1, 1, "a")).ParamName, Is.EqualTo("reader"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => CsvTable.Stream(null, "R.csv", 1, 1, new[] { "a" }, none, new bool[0])).ParamName, Is.EqualTo("reader"));
            SaysWhy(Assert.Throws<ArgumentException>(() => CsvTable.Stream(reader, "R.csv", 1, 1)));
            SaysWhy(Assert.Throws<ArgumentException>(() => CsvTable.Stream(reader, "R.csv", 1, 1, (string[])null)));
            SaysWhy(Assert.Throws<ArgumentException>(() => CsvTable.Stream(reader, "R.csv", 1, 1, none, none, new bool[0])));
            SaysWhy(Assert.Throws<ArgumentException>(() => CsvTable.Stream(reader, "R.csv", 1, 1, null, none, new bool[0])));
            SaysWhy(Assert.Throws<ArgumentException>(() => CsvTable.Stream(reader, "R.csv", 1, 1, new[] { "a" }, new[] { "b" }, new bool[0])));
            SaysWhy(Assert.Throws<ArgumentException>(() => CsvTable.Stream(reader, "R.csv", 1, 1, new[] { "a" }, null, new bool[0])));
            SaysWhy(Assert.Throws<ArgumentException>(() => CsvTable.Stream(reader, "R.csv", 1, 1, new[] { "a" }, new[] { "b" }, null)));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => CsvTable.Stream(reader, "R.csv", -1, 1, "a")).ParamName, Is.EqualTo("maxRows"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => CsvTable.Stream(reader, "R.csv", 1, -1, "a")).ParamName, Is.EqualTo("maxCharacters"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => CsvTable.Stream(reader, "R.csv", -1, 1, new[] { "a" }, none, new bool[0])).ParamName, Is.EqualTo("maxRows"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => CsvTable.Stream(reader, "R.csv", 1, -1, new[] { "a" }, none, new bool[0])).ParamName, Is.EqualTo("maxCharacters"));
            Assert.That(new List<CsvTable.Row>(CsvTable.Stream(new StringReader("a\n"), "R.csv", 0, 0, new[] { "a" }, none, new bool[0])), Is.Empty, "limits of 0 are limits");
        }

        [Test]
        public void TheSourceIsClosedOnceItsRowsAreRead()
        {
            var reader = new WatchedReader("a\n1\n");
            foreach (var row in CsvTable.Stream(reader, "R.csv", "a")) Assert.That(row[0], Is.EqualTo("1"));
            Assert.That(reader.Disposed, Is.True);
        }

        [TestCase("\"Max\" 1")]
        [TestCase(",left")]
        [TestCase("\nP1")]
        [TestCase("P1, left")]
        public void AFieldStartingWithAQuoteOrACommaIsQuotedAndReadsBack(string participant)
        {
            string escaped = CsvTable.Escape(participant);
            Assert.That(escaped, Does.StartWith("\"").And.EndWith("\""));
            var table = CsvTable.Parse("participant,n\n" + escaped + ",1\n", "R.csv", "participant", "n");
            Assert.That(table.Rows[0][0], Is.EqualTo(participant));
        }
    }
}
