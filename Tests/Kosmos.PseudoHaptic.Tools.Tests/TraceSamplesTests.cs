using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Cli.Traces;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>demo's and accuracy's trace reading in bounded memory (issue 12): 1 kHz whole, faster thinned, spans bounded.</summary>
public class TraceSamplesTests
{
    static string File(string text)
    {
        string path = Path.Combine(Path.GetTempPath(), "ph-samples-" + Guid.NewGuid().ToString("N")[..8] + ".csv");
        System.IO.File.WriteAllText(path, text);
        return path;
    }

    static string Rows(int count, double step, string format)
    {
        var sb = new StringBuilder("t,hand_y\n");
        for (int i = 0; i < count; i++) sb.Append((i * step).ToString(format, CultureInfo.InvariantCulture)).Append(",0.8\n");
        return sb.ToString();
    }

    [TestCase("F3")]
    [TestCase("R")]
    public void ATraceAt1KHzIsTakenWhole(string format)
    {
        string path = File(Rows(5001, 0.001, format));
        try
        {
            var (times, _) = TraceSamples.Read("--trace", path, "demo", usePoseTime: false, TraceSamples.DemoMaxSpan);
            Assert.That(times, Has.Count.EqualTo(5001));
        }
        finally { System.IO.File.Delete(path); }
    }

    [Test]
    public void AFasterTraceIsThinnedToOneSampleAMillisecond()
    {
        string path = File(Rows(100_001, 0.00001, "R"));
        try
        {
            var (times, _) = TraceSamples.Read("--trace", path, "accuracy", usePoseTime: true, TraceSamples.AccuracyMaxSpan);
            Assert.That(times.Count, Is.InRange(1000, 1001));
            for (int i = 1; i < times.Count; i++) Assert.That(times[i] - times[i - 1], Is.GreaterThanOrEqualTo(0.001 - 1e-9));
        }
        finally { System.IO.File.Delete(path); }
    }

    [Test]
    public void AUsableRowBeyondTheSpanIsRefusedNamingItsLine()
    {
        string path = File("t,hand_y,tracked\n-5,0.8,0\n0,0.8,1\n100,0.9,1\n120.5,0.9,1\n");
        try
        {
            var e = Assert.Throws<CliException>(() => TraceSamples.Read("--trace", path, "accuracy", usePoseTime: true, TraceSamples.AccuracyMaxSpan))!;
            Assert.That(e.Message, Does.Contain(":5: t = 120.5 s lies 120.5 s after the first usable row (line 3)"));
        }
        finally { System.IO.File.Delete(path); }
    }
}
