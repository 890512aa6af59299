using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli.Files;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// The tool as an adversarial user runs it (issue 12), each case on the built tool in a child process: an
/// output that is an input by any spelling, special files, empty/folder/missing paths, concurrent writers,
/// signals, long names, endless lines, huge spans, malformed and quoted CSV, control characters. Every case
/// checks the exit code, one line on stderr, the output (none, or the old one untouched) and no litter.
/// </summary>
[NonParallelizable]
public class AdversarialCliTests
{
    const string Responses = "participant,questionnaire,item,response\nP1,immersion,1,4\nP1,immersion,2,3\n";
    const string Scores = "participant,questionnaire,score\nP1,immersion,4.5\nP2,immersion,3\n";
    string _dir = "";

    [SetUp]
    public void SetUp()
    {
        if (!ToolProcess.IsLinux) Assert.Ignore("the adversarial cases use Linux file kinds, signals and /proc");
        _dir = Path.Combine(Path.GetTempPath(), "ph-adv-" + Guid.NewGuid().ToString("N")[..8]);
        Directory.CreateDirectory(_dir);
        if (TestContext.CurrentContext.Test.MethodName is "AnEmptyOutputPathIsRefused" or "AFolderOrAMissingParentAsAnOutputFileIsRefused" or "AFolderCommandRefusesAFileAMissingParentAndAForeignFolder")
        {
            Write("in.csv", Lift());
            Write("R.csv", Responses);
            Write("S.csv", Scores);
        }
    }

    [TearDown]
    public void TearDown()
    {
        if (_dir.Length > 0 && Directory.Exists(_dir)) Directory.Delete(_dir, recursive: true);
    }

    string Write(string name, string text)
    {
        string path = Path.Combine(_dir, name);
        File.WriteAllText(path, text);
        return path;
    }

    static string Lift(int rows = 300)
    {
        var sb = new StringBuilder("t,hand_y,tracked,pose_t\n");
        for (int i = 0; i < rows; i++)
        {
            double t = i / 90.0, pt = Math.Floor(t * 30) / 30, s = Math.Clamp((pt - 0.5) / 1.2, 0, 1);
            sb.Append(CultureInfo.InvariantCulture, $"{t:R},{0.8 + 0.3 * s * s * (3 - 2 * s):R},1,{pt:R}\n");
        }
        return sb.ToString();
    }

    ToolProcess.Result Run(params string[] args) => ToolProcess.Run(_dir, args);

    /// <summary>Exit code, exactly one line on stderr holding every expected piece.</summary>
    static void Refused(ToolProcess.Result r, int code, params string[] pieces)
    {
        Assert.That(r.Code, Is.EqualTo(code), r.Stderr);
        string line = r.Stderr.TrimEnd('\n');
        Assert.That(line, Does.Not.Contain('\n').And.Not.Contain('\r'), "one line: " + r.Stderr);
        Assert.That(line, Does.Not.Contain("   at ").And.Not.Contain("Exception"), "no stack trace");
        foreach (var p in pieces) Assert.That(line, Does.Contain(p));
    }

    /// <summary>The folder holds exactly these names: nothing half-written, no temporary files.</summary>
    void Holds(params string[] names)
        => Assert.That(Directory.GetFileSystemEntries(_dir).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal),
            Is.EqualTo(names.OrderBy(n => n, StringComparer.Ordinal)));

    // ---- an output that is an input -------------------------------------------------------------------

    [TestCase("in.csv")]
    [TestCase("./in.csv")]
    [TestCase("sub/../in.csv")]
    [TestCase("ABSOLUTE")]
    [TestCase("link.csv")]
    [TestCase("hard.csv")]
    [TestCase("sublink/in.csv")]
    public void ReplayNeverOverwritesItsTrace(string spelling)
    {
        string trace = Write("in.csv", Lift());
        Directory.CreateDirectory(Path.Combine(_dir, "sub"));
        File.CreateSymbolicLink(Path.Combine(_dir, "link.csv"), "in.csv");
        File.CreateSymbolicLink(Path.Combine(_dir, "sublink"), _dir);
        Assert.That(Link(trace, Path.Combine(_dir, "hard.csv")), Is.EqualTo(0));
        string output = spelling == "ABSOLUTE" ? trace : spelling;
        var r = Run("replay", "--trace", "in.csv", "--out", output, "--mass-kg", "1");
        Refused(r, 2, $"--out {output} is the same file as --trace in.csv");
        Assert.That(File.ReadAllText(trace), Is.EqualTo(Lift()));
        Holds("in.csv", "link.csv", "hard.csv", "sub", "sublink");
    }

    [Test]
    public void ScoreAccuracyAndReportNeverOverwriteTheirInputs()
    {
        Write("R.csv", Responses);
        Refused(Run("score", "--responses", "R.csv", "--out", "./R.csv"), 2, "--out ./R.csv is the same file as --responses R.csv");
        Write("trace.csv", Lift(200));
        File.CreateSymbolicLink(Path.Combine(_dir, "t2.csv"), Path.Combine(_dir, "trace.csv"));
        Refused(Run("accuracy", "--trace", "trace.csv", "--lifts", "none", "--mocap", "none", "--csv", "t2.csv"), 2, "--csv t2.csv is the same file as --trace trace.csv");
        Directory.CreateDirectory(Path.Combine(_dir, "rep"));
        File.WriteAllText(Path.Combine(_dir, "rep", "S.csv"), Scores);
        Refused(Run("report", "--scores", "rep/S.csv", "--out", "rep"), 2, "--out rep holds --scores rep/S.csv");
        Assert.That(File.ReadAllText(Path.Combine(_dir, "rep", "S.csv")), Is.EqualTo(Scores));
        Assert.That(File.ReadAllText(Path.Combine(_dir, "R.csv")), Is.EqualTo(Responses));
        Assert.That(File.ReadAllText(Path.Combine(_dir, "trace.csv")), Is.EqualTo(Lift(200)));
        Holds("R.csv", "trace.csv", "t2.csv", "rep");
    }

    // ---- special files, standard output ------------------------------------------------------------------

    [Test]
    public void ADeviceIsWrittenThroughNeverReplaced()
    {
        Write("in.csv", Lift());
        var before = FileIdentity.Of("/dev/null");
        Assert.That(before.Kind, Is.EqualTo(FileKind.CharacterDevice));
        var r = Run("replay", "--trace", "in.csv", "--out", "/dev/null", "--mass-kg", "1");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(FileIdentity.Of("/dev/null"), Is.EqualTo(before), "the same device node");
        Assert.That(Directory.GetFiles("/dev", ".ph*"), Is.Empty, "no temporary file in /dev");
        var full = Run("replay", "--trace", "in.csv", "--out", "/dev/full", "--mass-kg", "1");
        Refused(full, 1, "--out /dev/full: cannot write");
        Holds("in.csv");
    }

    [Test]
    public void AFifoIsWrittenThroughAndStaysAFifo()
    {
        Write("in.csv", Lift());
        string fifo = Path.Combine(_dir, "pipe");
        ToolProcess.MakeFifo(fifo);
        var reader = Task.Run(() => File.ReadAllText(fifo));
        var r = Run("replay", "--trace", "in.csv", "--out", "pipe", "--mass-kg", "1");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(reader.Wait(TimeSpan.FromSeconds(30)), Is.True);
        Assert.That(reader.Result.Split('\n', StringSplitOptions.RemoveEmptyEntries), Has.Length.EqualTo(301));
        Assert.That(FileIdentity.Of(fifo).Kind, Is.EqualTo(FileKind.Fifo), "still a FIFO, not a regular file");
        Holds("in.csv", "pipe");
    }

    [Test]
    public void DashIsStandardOutputAndTheSummaryMovesToStandardError()
    {
        Write("in.csv", Lift());
        var r = Run("replay", "--trace", "in.csv", "--out", "-", "--mass-kg", "1");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(r.Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries), Has.Length.EqualTo(301));
        Write("R.csv", Responses);
        var s = Run("score", "--responses", "R.csv", "--out", "-");
        Assert.That(s.Code, Is.EqualTo(0), s.Stderr);
        Assert.That(s.Stdout, Does.StartWith("participant,questionnaire,score\n"));
        Assert.That(s.Stderr, Does.Contain("scores of 1 participants"));
        Holds("in.csv", "R.csv");
    }

    // ---- empty path, folder, missing parent ------------------------------------------------------------

    [TestCase("replay", "--out")]
    [TestCase("score", "--out")]
    [TestCase("report", "--out")]
    [TestCase("demo", "--out")]
    [TestCase("accuracy", "--csv")]
    public void AnEmptyOutputPathIsRefused(string command, string option)
    {
        var r = Run(Args(command, option, ""));
        Refused(r, 2, $"option {option}: the path is empty");
        Holds("in.csv", "R.csv", "S.csv");
    }

    [TestCase("replay", "--out")]
    [TestCase("score", "--out")]
    [TestCase("accuracy", "--csv")]
    public void AFolderOrAMissingParentAsAnOutputFileIsRefused(string command, string option)
    {
        Directory.CreateDirectory(Path.Combine(_dir, "folder"));
        Refused(Run(Args(command, option, "folder")), 2, $"{option} folder: is a folder");
        Refused(Run(Args(command, option, "nowhere/x.csv")), 2, $"{option} nowhere/x.csv: the folder nowhere does not exist");
        Holds("in.csv", "R.csv", "S.csv", "folder");
    }

    [Test]
    public void AFolderCommandRefusesAFileAMissingParentAndAForeignFolder()
    {
        Write("x.txt", "mine");
        Refused(Run(Args("report", "--out", "x.txt")), 2, "--out x.txt: is a file, not a folder");
        Refused(Run(Args("report", "--out", "no/such")), 2, "--out no/such: the folder no does not exist");
        Directory.CreateDirectory(Path.Combine(_dir, "mine"));
        File.WriteAllText(Path.Combine(_dir, "mine", "notes.txt"), "keep");
        Refused(Run(Args("report", "--out", "mine")), 2, "--out mine: is a folder holding notes.txt");
        Assert.That(File.ReadAllText(Path.Combine(_dir, "mine", "notes.txt")), Is.EqualTo("keep"));
        Holds("in.csv", "R.csv", "S.csv", "x.txt", "mine");
    }

    [Test]
    public void AReportFolderAppearsWholeAndReplacesAnEarlierReportWhole()
    {
        Write("S.csv", Scores);
        var r = Run("report", "--scores", "S.csv", "--out", "rep");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        var first = Directory.GetFiles(Path.Combine(_dir, "rep")).Select(Path.GetFileName).OrderBy(n => n).ToArray();
        Assert.That(first, Does.Contain("report.md"));
        File.WriteAllText(Path.Combine(_dir, "rep", "table9-old.csv"), "stale");
        r = Run("report", "--scores", "S.csv", "--out", "rep");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(Directory.GetFiles(Path.Combine(_dir, "rep")).Select(Path.GetFileName).OrderBy(n => n).ToArray(), Is.EqualTo(first), "old files gone with the old folder");
        Holds("S.csv", "rep");
        // A malformed input: the earlier report stays as it was, nothing else appears.
        Write("bad.csv", "participant,questionnaire,score\nP1,immersion,9\n");
        Refused(Run("report", "--scores", "bad.csv", "--out", "rep"), 2, "bad.csv:2:");
        Assert.That(Directory.GetFiles(Path.Combine(_dir, "rep")).Select(Path.GetFileName).OrderBy(n => n).ToArray(), Is.EqualTo(first));
        Holds("S.csv", "bad.csv", "rep");
    }

    [Test]
    public void DemoWithOneUsableRowCreatesNothing()
    {
        Write("one.csv", "t,hand_y,tracked\n0,0.8,1\n0.1,0.9,0\n");
        Refused(Run("demo", "--trace", "one.csv", "--out", "d"), 2, "one.csv: fewer than two usable rows");
        Holds("one.csv");
    }

    [Test]
    public void DemoOfAHandThatJumpsEnds()
    {
        // 20 s of a hand jumping 0.3 m every second: the dashed hand line used to loop for ever in the chart.
        var sb = new StringBuilder("t,hand_y\n");
        for (int i = 0; i < 2000; i++) sb.Append(CultureInfo.InvariantCulture, $"{i / 100.0:R},{(i % 200 < 100 ? 0.8 : 1.1):R}\n");
        Write("steps.csv", sb.ToString());
        var r = ToolProcess.Run(_dir, TimeSpan.FromSeconds(90), "demo", "--trace", "steps.csv", "--out", "d");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(File.Exists(Path.Combine(_dir, "d", "recorded-hand.png")), Is.True);
        Holds("steps.csv", "d");
    }

    // ---- concurrent writers, signals, long names --------------------------------------------------------

    [Test]
    public void TwoWritersOfOneNewOutputBothSucceed()
    {
        Write("in.csv", Lift());
        for (int round = 0; round < 4; round++)
        {
            string output = $"o{round}.csv";
            var a = Task.Run(() => Run("replay", "--trace", "in.csv", "--out", output, "--mass-kg", "1"));
            var b = Task.Run(() => Run("replay", "--trace", "in.csv", "--out", output, "--mass-kg", "2"));
            Assert.That(a.Result.Code, Is.EqualTo(0), a.Result.Stderr);
            Assert.That(b.Result.Code, Is.EqualTo(0), b.Result.Stderr);
            Assert.That(File.ReadAllLines(Path.Combine(_dir, output)), Has.Length.EqualTo(301), "one whole file");
        }
        Holds("in.csv", "o0.csv", "o1.csv", "o2.csv", "o3.csv");
    }

    [TestCase(15, 143)]
    [TestCase(2, 130)]
    public void ASignalRemovesTheTemporaryFile(int signal, int exitCode)
    {
        // The trace comes through a FIFO that the test holds open, so the tool is caught mid-write.
        string fifo = Path.Combine(_dir, "trace.fifo");
        ToolProcess.MakeFifo(fifo);
        using var p = ToolProcess.Start(_dir, new[] { "replay", "--trace", "trace.fifo", "--out", "out.csv", "--mass-kg", "1" });
        using (var writer = new StreamWriter(fifo))
        {
            writer.Write(Lift(5000));
            writer.Flush();
            var deadline = DateTime.UtcNow.AddSeconds(30);
            while (Directory.GetFiles(_dir, ".ph*").Length == 0 && DateTime.UtcNow < deadline) Thread.Sleep(20);
            Assert.That(Directory.GetFiles(_dir, ".ph*"), Is.Not.Empty, "the temporary file is being written");
            ToolProcess.Signal(p, signal);
            Assert.That(p.WaitForExit(30_000), Is.True);
        }
        Assert.That(p.ExitCode, Is.EqualTo(exitCode));
        Holds("trace.fifo");
    }

    [TestCase(255)]
    [TestCase(250)]
    [TestCase(242)]
    public void LongOutputNamesWork(int length)
    {
        Write("in.csv", Lift());
        string name = new string('n', length - 4) + ".csv";
        var r = Run("replay", "--trace", "in.csv", "--out", name, "--mass-kg", "1");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Holds("in.csv", name);
        string tooLong = new string('n', 256) + ".csv";
        Refused(Run("replay", "--trace", "in.csv", "--out", tooLong, "--mass-kg", "1"), 1, "cannot write");
        Holds("in.csv", name);
    }

    // ---- malformed and quoted CSV, messages ------------------------------------------------------------

    [Test]
    public void QuotedFieldsAndFieldCountsInATrace()
    {
        Write("q.csv", "note,t,hand_y\n\"x,5,6,y\",0,1\n\"two\nlines\",0.1,1.1\n");
        var r = Run("replay", "--trace", "q.csv", "--out", "o.csv", "--mass-kg", "1");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        var lines = File.ReadAllLines(Path.Combine(_dir, "o.csv"));
        Assert.That(lines[1], Does.StartWith("0,1,"), "t from its own column, not from inside the quotes");
        Assert.That(lines[2], Does.StartWith("0.1,1.1,"));
        Write("extra.csv", "t,hand_y\n0,1\n0,1,5\n");
        Refused(Run("replay", "--trace", "extra.csv", "--out", "e.csv", "--mass-kg", "1"), 2, "extra.csv:3: expected 2 fields as in the header, found 3");
        Write("few.csv", "t,hand_y,tracked\n0,1,1\n0.1,1\n");
        Refused(Run("replay", "--trace", "few.csv", "--out", "e.csv", "--mass-kg", "1"), 2, "few.csv:3: expected 3 fields as in the header, found 2");
        Write("R.csv", "participant,questionnaire,item,response\n\"P,1\",immersion,1,4\nP2,immersion,1,4,9\n");
        Refused(Run("score", "--responses", "R.csv", "--out", "s.csv"), 2, "R.csv:3: expected 4 fields");
        Holds("q.csv", "o.csv", "extra.csv", "few.csv", "R.csv");
    }

    [Test]
    public void BomAndCrlfAreReadAlike()
    {
        File.WriteAllBytes(Path.Combine(_dir, "a.csv"), Encoding.UTF8.GetPreamble().Concat(Encoding.UTF8.GetBytes(Lift().Replace("\n", "\r\n"))).ToArray());
        Write("b.csv", Lift());
        Assert.That(Run("replay", "--trace", "a.csv", "--out", "oa.csv", "--mass-kg", "1").Code, Is.EqualTo(0));
        Assert.That(Run("replay", "--trace", "b.csv", "--out", "ob.csv", "--mass-kg", "1").Code, Is.EqualTo(0));
        Assert.That(File.ReadAllText(Path.Combine(_dir, "oa.csv")), Is.EqualTo(File.ReadAllText(Path.Combine(_dir, "ob.csv"))));
    }

    [Test]
    public void ControlCharactersInPathsAndContentAreShownEscaped()
    {
        var r = Run("replay", "--trace", "no\nsuch\u001b[31m.csv", "--out", "o.csv", "--mass-kg", "1");
        Refused(r, 2, "--trace no\\nsuch\\x1B[31m.csv: does not exist");
        Write("esc.csv", "t,hand_y\n0,1\n\u001b[2J\u0007,1\n");
        r = Run("replay", "--trace", "esc.csv", "--out", "o.csv", "--mass-kg", "1");
        Refused(r, 2, "esc.csv:3: column 't': cannot parse '\\x1B[2J\\x07'");
        Assert.That(r.Stderr, Does.Not.Contain("\u001b"));
        Refused(Run("replay", "--trace", _dir, "--out", "o.csv", "--mass-kg", "1"), 2, "is a folder");
        Holds("esc.csv");
    }

    [Test]
    public void AnErrorOnAProcPathNamesTheUsersPath()
    {
        Write("in.csv", Lift());
        var r = Run("replay", "--trace", "in.csv", "--out", "/proc/version", "--mass-kg", "1");
        Refused(r, 1, "--out /proc/version: cannot write");
        Assert.That(r.Stderr, Does.Not.Contain(".ph"));
    }

    static string[] Args(string command, string option, string value) => command switch
    {
        "replay" => new[] { "replay", "--trace", "in.csv", "--mass-kg", "1", option, value },
        "score" => new[] { "score", "--responses", "R.csv", option, value },
        "report" => new[] { "report", "--scores", "S.csv", option, value },
        "demo" => new[] { "demo", option, value },
        "accuracy" => new[] { "accuracy", "--trace", "in.csv", "--lifts", "none", "--mocap", "none", "--long-minutes", "0", option, value },
        _ => throw new ArgumentException(command),
    };

    [System.Runtime.InteropServices.DllImport("libc.so.6", EntryPoint = "link", SetLastError = true)]
    static extern int Link([System.Runtime.InteropServices.MarshalAs(System.Runtime.InteropServices.UnmanagedType.LPUTF8Str)] string from,
        [System.Runtime.InteropServices.MarshalAs(System.Runtime.InteropServices.UnmanagedType.LPUTF8Str)] string to);
}
