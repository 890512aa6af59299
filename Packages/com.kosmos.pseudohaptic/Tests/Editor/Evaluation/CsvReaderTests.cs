using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The one CSV reader as a study's files need it (RFC 4180 and the contract in evaluation.md §4): quoted fields
    /// with commas, quotes and line breaks, a byte-order mark, long free-text notes, a file delivered in pieces (a
    /// pipe, a slow disk), a file cut off by a power cut, and the row limit; every fault names FILE:LINE.
    /// </summary>
    public class CsvReaderTests
    {
        /// <summary>Serves its text at most <c>piece</c> characters a read, as a pipe or a network share does.</summary>
        sealed class PiecesReader : TextReader
        {
            readonly string text;
            readonly int piece;
            int position;
            bool ended;
            public int ReadsAfterEnd;
            public bool Disposed;

            public PiecesReader(string text, int piece)
            {
                this.text = text;
                this.piece = piece;
            }

            public override int Read(char[] buffer, int index, int count)
            {
                if (ended) ReadsAfterEnd++;
                int n = Math.Min(Math.Min(count, piece), text.Length - position);
                text.CopyTo(position, buffer, index, n);
                position += n;
                if (n == 0) ended = true;
                return n;
            }

            protected override void Dispose(bool disposing)
            {
                Disposed = true;
                base.Dispose(disposing);
            }
        }

        static List<string[]> ReadAll(CsvReader csv)
        {
            var rows = new List<string[]>();
            Assert.That(csv.ReadHeader(), Is.True);
            rows.Add(new List<string>(csv.Header).ToArray());
            while (csv.Read())
            {
                var fields = new string[csv.FieldCount];
                for (int i = 0; i < fields.Length; i++) fields[i] = csv[i];
                rows.Add(fields);
            }
            return rows;
        }

        static List<string[]> ReadAll(string text, int max = CsvReader.DefaultMaxRecordLength)
        {
            using (var csv = new CsvReader(new StringReader(text), "R.csv", max)) return ReadAll(csv);
        }

        static EvaluationFormatException Refused(string text, int max = CsvReader.DefaultMaxRecordLength)
            => Assert.Throws<EvaluationFormatException>(() => ReadAll(text, max));

        // A study's answers with everything RFC 4180 allows: a BOM, a quoted note with a comma and doubled quotes,
        // a quoted line break (CRLF), padding spaces, a blank line, a character U+FEFF inside a field (only a
        // leading one is a byte-order mark), a 2,000-character note followed by another field, and a last row
        // quoted to the end without a line break (a spreadsheet exporting every field quoted).
        static readonly string LongNote = new string('x', 1999) + "y";
        static readonly string StudyFile =
            "\uFEFFparticipant,note,response\r\n"
            + "P1,\"tired, but \"\"fine\"\"\",8\r\n"
            + "\r\n"
            + " P2 ,\"two\r\nlines\", 7 \r\n"
            + "P3,zero\uFEFFwidth,6\r\n"
            + "P4," + LongNote + ",5\r\n"
            + "\"P5\",\"" + LongNote + "\",\"4\"";

        static readonly string[][] StudyRows =
        {
            new[] { "participant", "note", "response" },
            new[] { "P1", "tired, but \"fine\"", "8" },
            new[] { "P2", "two\r\nlines", "7" },
            new[] { "P3", "zero\uFEFFwidth", "6" },
            new[] { "P4", LongNote, "5" },
            new[] { "P5", LongNote, "4" },
        };

        [Test]
        public void AStudysFileReadsAsRfc4180SaysWhole()
        {
            Assert.That(ReadAll(StudyFile), Is.EqualTo(StudyRows));
        }

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(7)]
        [TestCase(1000)]
        public void AFileDeliveredInPiecesReadsAsTheWholeFile(int piece)
        {
            var reader = new PiecesReader(StudyFile, piece);
            using (var csv = new CsvReader(reader, "R.csv"))
            {
                Assert.That(ReadAll(csv), Is.EqualTo(StudyRows));
                Assert.That(csv.Read(), Is.False, "still at the end");
            }
            Assert.That(reader.ReadsAfterEnd, Is.EqualTo(0), "a source that reported its end is not read again (a console would wait for a second end of input)");
        }

        [Test]
        public void AFreeTextNoteOfFiveThousandCharactersIsReadWholeAndSoIsTheFieldAfterIt()
        {
            string note = new string('x', 4999) + "y";
            Assert.That(ReadAll("note,response\n" + note + ",5\n")[1], Is.EqualTo(new[] { note, "5" }));
        }

        [Test]
        public void AByteOrderMarkArrivingAloneIsStillDropped()
        {
            var reader = new PiecesReader("\uFEFFa,b\n1,2\n", 1);
            using (var csv = new CsvReader(reader, "R.csv"))
                Assert.That(ReadAll(csv), Is.EqualTo(new[] { new[] { "a", "b" }, new[] { "1", "2" } }));
        }

        // A file saved empty by an editor that writes a byte-order mark has no header, whether the mark arrives
        // with the rest of the file or alone, and it is read once to its end.
        [TestCase(0)]
        [TestCase(1)]
        public void AFileOfNothingButAByteOrderMarkHasNoHeader(int piece)
        {
            foreach (string text in new[] { "\uFEFF", "\uFEFF \r\n\t\n" })
            {
                var reader = new PiecesReader(text, piece == 0 ? 1000 : piece);
                using (var csv = new CsvReader(reader, "R.csv"))
                {
                    Assert.That(csv.ReadHeader(), Is.False, text.Length.ToString());
                    Assert.That(csv.Read(), Is.False);
                }
                Assert.That(reader.ReadsAfterEnd, Is.EqualTo(0));
            }
        }

        [Test]
        public void ARowCutOffByAPowerCutEndsOnItsOwnLine()
        {
            using (var csv = new CsvReader(new StringReader("a,b\n1,22"), "R.csv"))
            {
                Assert.That(csv.ReadHeader(), Is.True);
                Assert.That(csv.Read(), Is.True);
                Assert.That(new[] { csv[0], csv[1] }, Is.EqualTo(new[] { "1", "22" }));
                Assert.That(new[] { csv.Line, csv.EndLine }, Is.EqualTo(new[] { 2, 2 }));
                Assert.That(csv.Read(), Is.False);
            }
        }

        [Test]
        public void ATailOfZerosLeftByAPowerCutIsARowWithTooFewFieldsOnItsLine()
        {
            var e = Refused("a,b\n1,2\n" + new string('\0', 3000));
            Assert.That(e.Line, Is.EqualTo(3));
            Assert.That(e.Reason, Does.Contain("expected 2 fields"));
        }

        [Test]
        public void AQuoteInsideAnUnquotedFieldNamesTheFieldAndTheRemedy()
        {
            var e = Refused("participant,note\nP1,say \"hi\"\n");
            Assert.That(e.Message, Does.StartWith("R.csv:2: "));
            Assert.That(e.Reason, Does.Contain("field 2"));
            Assert.That(e.Reason, Does.Contain("quote the whole field").And.Contain("double"), "says how to write it (RFC 4180 §2.7)");
        }

        [Test]
        public void AColumnNamedTwiceIsAnErrorOnTheHeadersLineEvenWhenItIsTheFirst()
        {
            using (var csv = new CsvReader(new StringReader("\n\nid,x,id\n"), "R.csv"))
            {
                Assert.That(csv.ReadHeader(), Is.True);
                var e = Assert.Throws<EvaluationFormatException>(() => csv.IndexOf("id"));
                Assert.That(e.Line, Is.EqualTo(3), "the header's line, after two blank lines");
                Assert.That(e.Reason, Does.Contain("column 'id'"));
                Assert.That(csv.IndexOf("x"), Is.EqualTo(1));
            }
        }

        // The limit: a record of exactly MaxRecordLength characters is accepted, one more is refused; the line
        // break that ends a record is not part of it ("line breaks inside quotes included"), so LF, CRLF and CR
        // files give the same verdict.
        [TestCase("\n")]
        [TestCase("\r\n")]
        [TestCase("\r")]
        public void ARowOfExactlyTheLimitIsReadWhateverItsLineEnd(string end)
        {
            string a = new string('9', 998) + ",9";  // 1,000 characters, the last one a field of its own
            string b = "9," + new string('9', 998);  // 1,000 characters, the last 998 in one run
            var rows = ReadAll("a,b" + end + a + end + b + end, max: 1000);
            Assert.That(rows.Count, Is.EqualTo(3));
            Assert.That(string.Join(",", rows[1]), Is.EqualTo(a));
            Assert.That(string.Join(",", rows[2]), Is.EqualTo(b));
        }

        [Test]
        public void ARowOfExactlyTheLimitCutOffWithoutALineEndIsRead()
        {
            string row = new string('9', 1000);
            Assert.That(ReadAll("a\n" + row, max: 1000)[1], Is.EqualTo(new[] { row }));
        }

        [TestCase(0)]
        [TestCase(3)]
        public void OneCharacterMoreThanTheLimitIsRefusedNamingTheLineAndTheLimit(int piece)
        {
            string text = "a,b\n1,2\n" + new string('9', 999) + ",9\n3,4\n";
            var e = Assert.Throws<EvaluationFormatException>(() =>
            {
                TextReader reader = piece == 0 ? (TextReader)new StringReader(text) : new PiecesReader(text, piece);
                using (var csv = new CsvReader(reader, "R.csv", 1000)) ReadAll(csv);
            });
            Assert.That(e.Message, Does.StartWith("R.csv:3: "));
            Assert.That(e.Reason, Does.Contain("longer").And.Contain("1000 characters"));
        }

        [TestCase(0)]
        [TestCase(7)]
        public void ARunawayRowIsRefusedWhereverItRunsAway(int piece)
        {
            // A field of 5,000 characters, a row of 3,000 empty fields, a quoted field that never closes.
            foreach (string row in new[] { new string('9', 5000) + ",1\n", new string(',', 3000) + "\n", "\"" + new string('9', 5000) + "\n" })
            {
                string text = "a,b\n1,2\n" + row;
                var e = Assert.Throws<EvaluationFormatException>(() =>
                {
                    TextReader reader = piece == 0 ? (TextReader)new StringReader(text) : new PiecesReader(text, piece);
                    using (var csv = new CsvReader(reader, "R.csv", 1000)) ReadAll(csv);
                }, row.Substring(0, 3));
                Assert.That(e.Line, Is.EqualTo(3), e.Message);
                Assert.That(e.Reason, Does.Contain("1000 characters"), e.Message);
            }
        }

        // Each line break inside quotes counts once, whichever it is (CRLF, a lone CR as old Mac files have, LF), so
        // the rows after a multi-line note are named on their own lines; a quoted last field ends its row at LF,
        // CRLF or CR like an unquoted one. Delivered whole and a character or two at a time (a CRLF split across
        // two reads is still one line break).
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        public void EachQuotedLineBreakCountsOnceWhateverItIsAndTheRowsAfterItKeepTheirLines(int piece)
        {
            string text = "participant,note\n"        // line 1
                + "P1,\"two\r\nlines\"\n"           // lines 2-3: CRLF inside, LF after
                + "P2,\"old\rmac\"\r\n"             // lines 4-5: CR inside, CRLF after
                + "P3,\"unix\nline\"\r"              // lines 6-7: LF inside, CR after
                + "P4,\"\r\n\r\n\"\n"               // lines 8-10: nothing but two CRLF
                + "P5,plain\n"                        // line 11
                + "P6\n";                             // line 12: one field short
            var expected = new[]
            {
                new object[] { "P1", "two\r\nlines", 2, 3 },
                new object[] { "P2", "old\rmac", 4, 5 },
                new object[] { "P3", "unix\nline", 6, 7 },
                new object[] { "P4", "\r\n\r\n", 8, 10 },
                new object[] { "P5", "plain", 11, 11 },
            };
            TextReader reader = piece == 0 ? (TextReader)new StringReader(text) : new PiecesReader(text, piece);
            using (var csv = new CsvReader(reader, "R.csv"))
            {
                Assert.That(csv.ReadHeader(), Is.True);
                foreach (var row in expected)
                {
                    Assert.That(csv.Read(), Is.True, (string)row[0]);
                    Assert.That(new object[] { csv[0], csv[1], csv.Line, csv.EndLine }, Is.EqualTo(row), (string)row[0]);
                }
                var e = Assert.Throws<EvaluationFormatException>(() => csv.Read());
                Assert.That(e.Message, Does.StartWith("R.csv:12: "), "the row after 4 quoted line breaks is on line 12");
            }
        }

        [Test]
        public void SpacesAndTabsAfterAClosingQuoteAreNotPartOfTheFieldNorAnError()
        {
            var rows = ReadAll("participant,note,response\n\"P1\"  ,\"fine\"\t, \"8\" \t\n\"P2\" ,\"ok\" ,\"7\"  ");
            Assert.That(rows, Is.EqualTo(new[] { new[] { "participant", "note", "response" }, new[] { "P1", "fine", "8" }, new[] { "P2", "ok", "7" } }));
        }

        // Text after the closing quote (a hand-edited `"say" hi`, or the zeros a power cut leaves right after a
        // quoted last field) is refused on the row's line, naming the field and the remedy; it is not read as
        // the start of another row.
        [TestCase("P1,\"say\" hi\n")]
        [TestCase("P1,\"say\"\0\0\0")]
        public void TextAfterAClosingQuoteIsRefusedNamingTheFieldAndTheRemedy(string row)
        {
            var e = Refused("participant,note\nP0,fine\n" + row);
            Assert.That(e.Message, Does.StartWith("R.csv:3: "), e.Message);
            Assert.That(e.Reason, Does.Contain("text after the closing quote of field 2"), e.Message);
            Assert.That(e.Reason, Does.Contain("(quote the whole field)"), e.Message);
        }

        // A long note costs memory in proportion to its length (the row's buffer doubles as it fills, up to the
        // row limit): a note of 20,000 characters (40 KB), arriving a character at a time or written as 10,000
        // doubled quotes, is read with less than 1 MB allocated in all (the 16,384-character read buffer
        // included). Growing the buffer a little at a time would copy hundreds of megabytes; growing it straight
        // to the 1 MiB limit would allocate over 2 MB for every such file.
        [TestCase(false)]
        [TestCase(true)]
        public void ALongNoteCostsMemoryInProportionToItsLength(bool doubledQuotes)
        {
            string note = doubledQuotes ? new string('"', 10000) : new string('x', 20000);
            string written = doubledQuotes ? "\"" + note.Replace("\"", "\"\"") + "\"" : note;
            string text = "note,response\n" + written + ",5\n";
            List<string[]> Read()
            {
                using (var csv = new CsvReader(new PiecesReader(text, 1), "R.csv")) return ReadAll(csv);
            }
            Read(); // compiled and warmed up: only the reading itself is measured
            long before = GC.GetAllocatedBytesForCurrentThread();
            var rows = Read();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.That(rows[1], Is.EqualTo(new[] { note, "5" }), "every character kept");
            Assert.That(allocated, Is.LessThan(1000000), "bytes allocated to read a 40 KB note");
        }

        [Test]
        public void TheLimitIsAtLeastOneCharacter()
        {
            Assert.That(ReadAll("a", max: 1)[0], Is.EqualTo(new[] { "a" }));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new CsvReader(new StringReader("a"), "R.csv", 0));
            Assert.That(e.ParamName, Is.EqualTo("maxRecordLength"));
            Assert.That(e.Message, Is.Not.EqualTo(new ArgumentException("", e.ParamName).Message), "says what it must be");
        }

        [Test]
        public void MisuseIsRefusedSayingWhy()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => new CsvReader(null, "R.csv")).ParamName, Is.EqualTo("reader"));
            using (var csv = new CsvReader(new StringReader("a\n1\n"), "R.csv"))
            {
                Assert.That(Assert.Throws<InvalidOperationException>(() => csv.IndexOf("a")).Message, Is.Not.Empty);
                Assert.That(csv.ReadHeader(), Is.True);
                Assert.That(Assert.Throws<InvalidOperationException>(() => csv.ReadHeader()).Message, Is.Not.Empty);
            }
        }

        [Test]
        public void AnUnnamedSourceIsNamedEmpty()
        {
            using (var csv = new CsvReader(new StringReader("a\n"), null)) Assert.That(csv.SourceName, Is.EqualTo(""));
        }

        [Test]
        public void DisposingClosesTheSourceUnlessAskedToLeaveItOpen()
        {
            var closed = new PiecesReader("a\n", 10);
            new CsvReader(closed, "R.csv").Dispose();
            Assert.That(closed.Disposed, Is.True);
            var open = new PiecesReader("a\n", 10);
            new CsvReader(open, "R.csv", leaveOpen: true).Dispose();
            Assert.That(open.Disposed, Is.False);
        }
    }
}
