using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>The one CSV reader (issue 12): RFC 4180, BOM, line ends, field counts, the row limit.</summary>
public class CsvReaderTests
{
    static List<string[]> ReadAll(string text, int max = CsvReader.DefaultMaxRecordLength)
    {
        using var csv = new CsvReader(new StringReader(text), "f.csv", max);
        var rows = new List<string[]>();
        Assert.That(csv.ReadHeader(), Is.True);
        rows.Add(csv.Header.ToArray());
        while (csv.Read())
        {
            var r = new string[csv.FieldCount];
            for (int i = 0; i < r.Length; i++) r[i] = csv[i];
            rows.Add(r);
        }
        return rows;
    }

    static string ErrorOf(string text, int max = CsvReader.DefaultMaxRecordLength)
        => Assert.Throws<EvaluationFormatException>(() => ReadAll(text, max))!.Message;

    [Test]
    public void QuotedFieldsHoldCommasLineBreaksAndDoubledQuotes()
    {
        var rows = ReadAll("a,b,c\n\"x,5,6,y\",\"line1\nline2\",\"say \"\"hi\"\"\"\n1,2,3\n");
        Assert.That(rows[1], Is.EqualTo(new[] { "x,5,6,y", "line1\nline2", "say \"hi\"" }));
        Assert.That(rows[2], Is.EqualTo(new[] { "1", "2", "3" }));
    }

    [Test]
    public void LinesAreCountedAcrossQuotedLineBreaks()
    {
        using var csv = new CsvReader(new StringReader("a,b\n\"1\n\n2\",3\n4,\"5\r\n6\"\n7,8\n"), "f.csv");
        csv.ReadHeader();
        Assert.That(csv.Read(), Is.True);
        Assert.That((csv.Line, csv.EndLine), Is.EqualTo((2, 4)));
        Assert.That(csv.Read(), Is.True);
        Assert.That((csv.Line, csv.EndLine), Is.EqualTo((5, 6)));
        Assert.That(csv[1], Is.EqualTo("5\r\n6"));
        Assert.That(csv.Read(), Is.True);
        Assert.That(csv.Line, Is.EqualTo(7));
        Assert.That(csv.Read(), Is.False);
    }

    [TestCase("\uFEFFa,b\r\n1,2\r\n")]
    [TestCase("a,b\n1,2")]
    [TestCase("a,b\r1,2\r")]
    [TestCase("\n  \na,b\n\n1,2\n\n")]
    [TestCase(" a , b \n 1 ,\t2 \n")]
    [TestCase("\"a\", \"b\"\n\"1\",2\n")]
    public void BomLineEndsBlankLinesAndSpacesReadAlike(string text)
    {
        var rows = ReadAll(text);
        Assert.That(rows, Is.EqualTo(new[] { new[] { "a", "b" }, new[] { "1", "2" } }));
    }

    [TestCase("a,b\n0,1,5\n", 2, "expected 2 fields as in the header, found 3")]
    [TestCase("a,b,c\n0,1\n", 2, "expected 3 fields as in the header, found 2")]
    [TestCase("a,b\n1,2\n\"3,4\n", 3, "unterminated quoted field")]
    [TestCase("a,b\n1,x\"y\n", 2, "a quote inside unquoted field 2")]
    [TestCase("a,b\n\"1\"x,2\n", 2, "text after the closing quote of field 1")]
    [TestCase("a,b\n\"1\n\",2\n3,4,5\n", 4, "found 3")]
    public void MalformedRowsAreErrorsNamingTheLine(string text, int line, string reason)
    {
        string message = ErrorOf(text);
        Assert.That(message, Does.StartWith($"f.csv:{line}: ").And.Contain(reason));
        Assert.That(message, Does.Not.Contain("\n"));
    }

    [Test]
    public void ARowLongerThanTheLimitIsRefusedNamingItsLine()
    {
        Assert.That(ErrorOf("a,b\n1,2\n" + new string('9', 5000) + ",1\n", max: 1000), Does.StartWith("f.csv:3: the row is longer than 1000 characters"));
        Assert.That(ErrorOf("a,b\n\"" + new string('9', 5000), max: 1000), Does.StartWith("f.csv:2: the row is longer than 1000 characters"));
        Assert.That(ReadAll("a,b\n" + new string('9', 998) + ",1\r\n", max: 1000)[1][0], Has.Length.EqualTo(998), "exactly at the limit (line end not counted)");
    }

    [Test]
    public void AnEndlessLineStopsAtTheLimitWithoutReadingFurther()
    {
        var endless = new EndlessReader();
        using var csv = new CsvReader(endless, "/dev/zero");
        var e = Assert.Throws<EvaluationFormatException>(() => csv.ReadHeader())!;
        Assert.That(e.Message, Does.StartWith("/dev/zero:1: the row is longer than 1048576 characters"));
        Assert.That(endless.Served, Is.LessThan(CsvReader.DefaultMaxRecordLength + 65536));
    }

    [Test]
    public void RandomRoundTripsThroughEscapeReadBack()
    {
        var rng = new Random(12);
        const string alphabet = "ab ,\"\n\r\t;x\u00e9\u2028";
        for (int seed = 0; seed < 300; seed++)
        {
            int columns = 1 + rng.Next(4);
            var rows = new List<string[]>();
            for (int r = 0; r < 1 + rng.Next(5); r++)
            {
                var row = new string[columns];
                for (int c = 0; c < columns; c++)
                {
                    var chars = new char[rng.Next(6)];
                    for (int k = 0; k < chars.Length; k++) chars[k] = alphabet[rng.Next(alphabet.Length)];
                    row[c] = "v" + new string(chars) + "w"; // edge spaces are trimmed by design; keep them inside
                }
                rows.Add(row);
            }
            var header = Enumerable.Range(0, columns).Select(i => "c" + i).ToArray();
            string newline = rng.Next(2) == 0 ? "\n" : "\r\n";
            string text = string.Join(",", header) + newline + string.Concat(rows.Select(r => string.Join(",", r.Select(CsvTable.Escape)) + newline));
            var read = ReadAll(text);
            Assert.That(read.Skip(1).ToList(), Is.EqualTo(rows), "seed " + seed);
        }
    }

    sealed class EndlessReader : TextReader
    {
        public long Served;

        public override int Read(char[] buffer, int index, int count)
        {
            Array.Fill(buffer, '\0', index, count);
            Served += count;
            return count;
        }
    }
}
