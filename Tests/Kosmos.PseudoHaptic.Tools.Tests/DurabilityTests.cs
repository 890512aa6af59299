using System.Diagnostics;
using System.Globalization;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Study data that survives a crash and a power cut (issue 35), tested on the writer as the headset runs it: the
/// package's DiscriminationTaskModel and QuestionnairePanelModel over one background SaveQueue, in a child process
/// (Tests/Kosmos.PseudoHaptic.DurabilityChild) that acknowledges each answer on standard output.
/// <list type="bullet">
/// <item>the order of system calls under strace: each acknowledged answer's temporary file fsynced before its rename,
/// the folder fsynced after it, both before the acknowledgement;</item>
/// <item>SIGKILL at seeded random instants (20 here; PSEUDOHAPTIC_KILLS=1000 for the long run): the files always parse,
/// the next child resumes where the last stopped, every acknowledged answer is in its file exactly once, the temporary
/// files a kill left are removed when the next session begins, and none is left once a final, unkilled resume has finished;</item>
/// <item>a full disk and a read-only folder (tmpfs mounts, as root): the answer is kept and the error said, no
/// temporary file is left, and the answer is written once when the disk has room again.</item>
/// </list>
/// </summary>
[NonParallelizable]
public class DurabilityTests
{
    static string ChildDll => Path.Combine(AppContext.BaseDirectory, "Kosmos.PseudoHaptic.DurabilityChild.dll");

    string _dir = "";

    [SetUp]
    public void SetUp()
    {
        _dir = Path.Combine(Path.GetTempPath(), "ph-durable-" + Guid.NewGuid().ToString("N")[..8]);
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void TearDown()
    {
        if (_mounted != null) Run("umount", "-l", _mounted);
        _mounted = null;
        if (Directory.Exists(_dir)) Directory.Delete(_dir, recursive: true);
    }

    // ---------------------------------------------------------------------------------------------- strace

    [Test]
    public void UnderStraceEveryAcknowledgedAnswerIsSyncedBeforeItsRenameAndItsFolderAfter()
    {
        string strace = RequireStrace();
        var (acks, violations) = TracedRun(strace, Path.Combine(_dir, "synced"), unsynced: false);
        Assert.That(acks, Is.EqualTo(8 + 8), "8 trials and 8 items acknowledged");
        Assert.That(violations, Is.Empty);

        // The check can fail: the same writer with the syncs switched off breaks it for every answer.
        var (unsyncedAcks, unsyncedViolations) = TracedRun(strace, Path.Combine(_dir, "unsynced"), unsynced: true);
        Assert.That(unsyncedAcks, Is.EqualTo(16));
        Assert.That(unsyncedViolations.Count(v => v.Contains("not fsynced before its rename")), Is.EqualTo(16), string.Join("\n", unsyncedViolations));
        Assert.That(unsyncedViolations.Count(v => v.Contains("folder not fsynced")), Is.EqualTo(16), string.Join("\n", unsyncedViolations));
    }

    /// <summary>Runs the durability child with <paramref name="childArgs"/> under strace, writing the calls named in
    /// <paramref name="syscalls"/> to <paramref name="trace"/> (with the syncs switched off when <paramref name="unsynced"/>);
    /// returns its standard output. Ignored where strace cannot trace; fails when the child hangs or fails.</summary>
    static string RunChildUnderStrace(string strace, string trace, bool unsynced, string syscalls, params string[] childArgs)
        => RunChildUnderStrace(strace, trace, unsynced, syscalls, null, childArgs);

    /// <summary>As above; <paramref name="inject"/>, if given, is strace's fault injection (<c>-e inject=…</c>).</summary>
    static string RunChildUnderStrace(string strace, string trace, bool unsynced, string syscalls, string? inject, string[] childArgs)
    {
        var info = new ProcessStartInfo(strace)
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            ArgumentList = { "-f", "-o", trace, "-e", "trace=" + syscalls },
        };
        if (inject != null) { info.ArgumentList.Add("-e"); info.ArgumentList.Add("inject=" + inject); }
        info.ArgumentList.Add("dotnet");
        info.ArgumentList.Add(ChildDll);
        foreach (string a in childArgs) info.ArgumentList.Add(a);
        if (unsynced) info.Environment["PSEUDOHAPTIC_UNSYNCED"] = "1";
        using var p = Process.Start(info)!;
        string stdout = p.StandardOutput.ReadToEnd();
        string stderr = p.StandardError.ReadToEnd();
        Assert.That(p.WaitForExit(120_000), Is.True, "the traced child hung");
        if (p.ExitCode != 0 && stderr.Contains("ptrace", StringComparison.OrdinalIgnoreCase))
            Assert.Ignore("strace cannot trace here (ptrace refused): " + stderr.Trim());
        Assert.That(p.ExitCode, Is.Zero, stderr);
        return stdout;
    }

    (int acks, List<string> violations) TracedRun(string strace, string dir, bool unsynced)
    {
        Directory.CreateDirectory(dir);
        string trace = Path.Combine(_dir, (unsynced ? "unsynced" : "synced") + ".strace");
        string stdout = RunChildUnderStrace(strace, trace, unsynced, "fsync,fdatasync,rename,renameat,renameat2,openat,link,linkat",
            "participant", dir, "P1", "7", "2", "--marker");
        string[] acks = stdout.Split('\n').Where(l => l.StartsWith("ack ", StringComparison.Ordinal)).ToArray();
        var targets = acks.Select(a => Path.Combine(dir, a.StartsWith("ack trial ", StringComparison.Ordinal) ? "trials.csv" : "responses.csv")).ToList();
        return (acks.Length, StraceCheck.Violations(File.ReadAllLines(trace), dir, targets));
    }

    [Test]
    public void UnderStraceEveryRecordedHoldIsSyncedBeforeItsRenameAndItsFolderAfterBeforeItIsReportedWritten()
    {
        string strace = RequireStrace();
        var (acks, violations) = RecorderRun(strace, Path.Combine(_dir, "synced"), unsynced: false);
        Assert.That(acks, Is.EqualTo(3), "3 holds reported written");
        Assert.That(violations, Is.Empty);

        // The check can fail: the same recorder with the syncs switched off breaks it for every hold.
        var (unsyncedAcks, unsyncedViolations) = RecorderRun(strace, Path.Combine(_dir, "unsynced"), unsynced: true);
        Assert.That(unsyncedAcks, Is.EqualTo(3));
        Assert.That(unsyncedViolations.Count(v => v.Contains("not fsynced before its rename")), Is.EqualTo(3), string.Join("\n", unsyncedViolations));
        Assert.That(unsyncedViolations.Count(v => v.Contains("folder not fsynced")), Is.EqualTo(3), string.Join("\n", unsyncedViolations));
    }

    (int acks, List<string> violations) RecorderRun(string strace, string dir, bool unsynced)
    {
        Directory.CreateDirectory(dir);
        string trace = Path.Combine(_dir, (unsynced ? "unsynced" : "synced") + "-recorder.strace");
        string stdout = RunChildUnderStrace(strace, trace, unsynced, "fsync,fdatasync,rename,renameat,renameat2,openat,link,linkat",
            "recorder", dir, "3");
        Assert.That(stdout, Does.EndWith("done\n"));
        var files = stdout.Split('\n').Where(l => l.StartsWith("ack hold ", StringComparison.Ordinal)).Select(l => l["ack hold ".Length..]).ToList();
        Assert.That(files.All(f => Path.GetDirectoryName(f) == Path.Combine(dir, "P1")), Is.True, "the session's folder: " + string.Join(", ", files));
        return (files.Count, StraceCheck.Violations(File.ReadAllLines(trace), dir, files));
    }

    [Test]
    public void UnderStraceCreatedFoldersAndWriteWithAreSyncedAndEachTemporaryFileExactlyOnce()
    {
        string strace = RequireStrace();
        var synced = AtomicRun(strace, Path.Combine(_dir, "synced"), unsynced: false);
        Assert.That(synced, Is.Empty);

        // The check can fail: the same calls with the syncs switched off break every part of it.
        var unsynced = AtomicRun(strace, Path.Combine(_dir, "unsynced"), unsynced: true);
        Assert.That(unsynced.Count(v => v.Contains("folder above it not fsynced")), Is.EqualTo(2), string.Join("\n", unsynced));
        Assert.That(unsynced.Count(v => v.Contains("fsynced 0 times")), Is.EqualTo(2), string.Join("\n", unsynced));
        Assert.That(unsynced.Count(v => v.Contains("folder not fsynced")), Is.EqualTo(2), string.Join("\n", unsynced));
    }

    /// <summary>
    /// Runs the child's "atomic" mode under strace; returns what is wrong: a folder it created whose parent was not
    /// fsynced after the mkdir and before the first mark; for each of the two files, a temporary file not fsynced exactly
    /// once between its creation and its rename (data synced, and not twice), or the folder not fsynced after the rename
    /// and before its mark (StraceCheck).
    /// </summary>
    List<string> AtomicRun(string strace, string dir, bool unsynced)
    {
        Directory.CreateDirectory(dir);
        string trace = Path.Combine(_dir, (unsynced ? "unsynced" : "synced") + "-atomic.strace");
        string stdout = RunChildUnderStrace(strace, trace, unsynced, "fsync,fdatasync,rename,renameat,renameat2,openat,link,linkat,mkdir,mkdirat",
            "atomic", dir);
        Assert.That(stdout, Does.Contain("done"));
        string[] lines = File.ReadAllLines(trace);
        string deeper = Path.Combine(dir, "made", "deeper");
        // The two files' marks are the second and the third: the first (after CreateDirectory) is matched to no file.
        var violations = StraceCheck.Violations(lines.Where(l => !l.Contains("/.ack-1\"", StringComparison.Ordinal)), dir,
            new[] { Path.Combine(deeper, "with.csv"), Path.Combine(deeper, "text.csv") });

        var calls = StraceCheck.Parse(lines);
        var fdPath = new Dictionary<long, string>();
        var events = new List<(string kind, string path)>(); // mkdir, sync, create, move (source), mark
        foreach (var c in calls)
        {
            var paths = Regex.Matches(c.Args, "\"((?:[^\"\\\\]|\\\\.)*)\"").Select(q => q.Groups[1].Value).ToArray();
            if (paths.Length == 0 && c.Name != "fsync" && c.Name != "fdatasync") continue;
            switch (c.Name)
            {
                case "mkdir":
                case "mkdirat":
                    if (c.Result == 0) events.Add(("mkdir", paths[0].TrimEnd('/')));
                    break;
                case "openat":
                    if (c.Result >= 0)
                    {
                        fdPath[c.Result] = paths[0];
                        if (c.Args.Contains("O_CREAT", StringComparison.Ordinal)) events.Add(("create", paths[0]));
                    }
                    else if (Path.GetFileName(paths[0]).StartsWith(".ack-", StringComparison.Ordinal)) events.Add(("mark", paths[0]));
                    break;
                case "fsync":
                case "fdatasync":
                    if (c.Result == 0 && long.TryParse(c.Args.Split(',')[0].Trim(), out long fd) && fdPath.TryGetValue(fd, out string? synced))
                        events.Add(("sync", synced.TrimEnd('/')));
                    break;
                default:
                    if (c.Result == 0 && paths.Length >= 2) events.Add(("move", paths[0]));
                    break;
            }
        }
        int firstMark = events.FindIndex(e => e.kind == "mark");
        foreach (string made in new[] { Path.Combine(dir, "made"), deeper })
        {
            int mkdir = events.FindIndex(e => e.kind == "mkdir" && e.path == made);
            if (mkdir < 0 || firstMark < mkdir) { violations.Add(made + ": no mkdir before the first mark"); continue; }
            string parent = Path.GetDirectoryName(made)!;
            if (!events.Skip(mkdir + 1).Take(firstMark - mkdir - 1).Any(e => e.kind == "sync" && e.path == parent))
                violations.Add(made + ": the folder above it not fsynced after its mkdir and before the mark");
        }
        foreach (var move in events.Where(e => e.kind == "move" && Path.GetFileName(e.path).StartsWith(".ph", StringComparison.Ordinal)))
        {
            int at = events.IndexOf(move);
            int created = events.FindLastIndex(at, e => e.kind == "create" && e.path == move.path);
            int syncs = events.Skip(created + 1).Take(at - created - 1).Count(e => e.kind == "sync" && e.path == move.path);
            if (syncs != 1) violations.Add(Path.GetFileName(move.path) + ": the temporary file fsynced " + syncs + " times before its rename, not once");
        }
        return violations;
    }

    // ---------------------------------------------------------------------------------------------- injected sync failures
    // strace's fault injection makes one fsync of the child fail with a chosen errno. In the child's sync-fault mode the
    // first fsync is the temporary file's, the second the folder's after the rename (each checked in the trace).

    string[] SyncFault(string strace, string? inject, bool closeStdin = false, int fsyncs = 4)
    {
        string dir = Path.Combine(_dir, "fault");
        Directory.CreateDirectory(dir);
        string trace = Path.Combine(_dir, "fault.strace");
        var args = closeStdin ? new[] { "sync-fault", dir, "--close-stdin" } : new[] { "sync-fault", dir };
        string stdout = RunChildUnderStrace(strace, trace, false, "openat,fsync", inject, args);
        var syncs = StraceCheck.Parse(File.ReadAllLines(trace)).Where(c => c.Name == "fsync").ToList();
        Assert.That(syncs, Has.Count.EqualTo(fsyncs), "two writes: a file's fsync and a folder's each (none for a write whose file's failed)");
        return stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries);
    }

    [TestCase("EIO", 5)]
    [TestCase("45", 45)] // ENOTSUP on macOS, which refuses a folder's sync there; EL2NSYNC on Linux, a failure
    public void AFolderSyncThatFailsIsAnErrorNamingTheFolderAndTheErrnoAndTheNextWriteIsSynced(string error, int errno)
    {
        string[] lines = SyncFault(RequireStrace(), "fsync:error=" + error + ":when=2");
        string dir = Path.Combine(_dir, "fault");
        Assert.That(lines, Is.EqualTo(new[]
        {
            "error " + dir + ": the folder could not be synced to the device (errno " + errno + ")",
            "file first", // renamed, but not on the device: the write is reported failed, so the answer is not acknowledged
            "ok Synced", "file second", "temporaries 0",
        }));
    }

    [TestCase("EINVAL")]
    [TestCase("EOPNOTSUPP")]
    public void AFolderSyncTheFileSystemRefusesIsNoErrorAndIsSaidSo(string error)
    {
        string[] lines = SyncFault(RequireStrace(), "fsync:error=" + error + ":when=2");
        Assert.That(lines, Is.EqualTo(new[] { "ok Refused", "file first", "ok Synced", "file second", "temporaries 0" }));
    }

    [TestCase("EINVAL")]
    [TestCase("EOPNOTSUPP")]
    public void AFileSyncTheFileSystemRefusesIsNoError(string error)
    {
        string[] lines = SyncFault(RequireStrace(), "fsync:error=" + error + ":when=1");
        Assert.That(lines, Is.EqualTo(new[] { "ok Synced", "file first", "ok Synced", "file second", "temporaries 0" }));
    }

    [TestCase(1)]
    [TestCase(2)]
    public void AnFsyncInterruptedByASignalIsTriedAgain(int which)
    {
        // EINTR on the file's (1) or the folder's (2) fsync: not a failure, the call is made again.
        string[] lines = SyncFault(RequireStrace(), "fsync:error=EINTR:when=" + which, fsyncs: 5);
        Assert.That(lines, Is.EqualTo(new[] { "ok Synced", "file first", "ok Synced", "file second", "temporaries 0" }));
    }

    [Test]
    public void AFileSyncThatFailsIsAnErrorAndLeavesNeitherTheFileNorATemporaryOne()
    {
        string[] lines = SyncFault(RequireStrace(), "fsync:error=EIO:when=1", fsyncs: 3);
        Assert.That(lines, Has.Length.EqualTo(5), string.Join("\n", lines));
        Assert.That(lines[0], Does.Match(@"^error .*/fault/\.ph[0-9a-f]{8}\.tmp: the file could not be synced to the device \(errno 5\)$"), "the file's own sync failed");
        Assert.That(lines.Skip(1), Is.EqualTo(new[] { "file none", "ok Synced", "file second", "temporaries 0" }), "never renamed; the next write is whole");
    }

    [Test]
    public void WithStandardInputClosedTheFolderOpensAsDescriptorZeroAndIsSynced()
    {
        string[] lines = SyncFault(RequireStrace(), null, closeStdin: true);
        Assert.That(lines, Is.EqualTo(new[] { "ok Synced", "file first", "ok Synced", "file second", "temporaries 0" }));
        string dir = Path.Combine(_dir, "fault");
        var opens = StraceCheck.Parse(File.ReadAllLines(Path.Combine(_dir, "fault.strace"))).Where(c => c.Name == "openat" && c.Args.Contains("\"" + dir + "\"", StringComparison.Ordinal));
        Assert.That(opens.Select(c => c.Result).Last(), Is.Zero, "the second write's folder really was descriptor 0, a valid one");
    }

    [Test]
    public void ASessionWhoseFolderSyncFailsDoesNotAcknowledgeTheAnswerSaysSoAndWritesItOnceOnRetry()
    {
        string strace = RequireStrace();
        string dir = Path.Combine(_dir, "session");
        Directory.CreateDirectory(dir);
        string trace = Path.Combine(_dir, "session.strace");
        // The background writer's second fsync: the first answer's folder, after its rename.
        string stdout = RunChildUnderStrace(strace, trace, false, "fsync,rename,openat", "fsync:error=EIO:when=2",
            new[] { "participant", dir, "P1", "7", "2", "--marker" });
        string[] lines = stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        int error = Array.FindIndex(lines, l => l.StartsWith("error trial ", StringComparison.Ordinal));
        int firstAck = Array.FindIndex(lines, l => l.StartsWith("ack ", StringComparison.Ordinal));
        Assert.That(error, Is.GreaterThan(0), "the failure is said: " + stdout);
        Assert.That(lines[error], Does.Contain(DiscriminationTaskModel.NotSavedPrefix).And.Contain("errno 5"));
        Assert.That(firstAck, Is.GreaterThan(error), "the first answer is acknowledged only after its write succeeded");
        Assert.That(lines.Count(l => l.StartsWith("ack ", StringComparison.Ordinal)), Is.EqualTo(16), "every answer acknowledged once");
        Assert.That(lines.Last(), Is.EqualTo("done"));
        string[] trials = File.ReadAllLines(Path.Combine(dir, "trials.csv"));
        Assert.That(trials.Skip(1).Select(r => r.Split(',')[2]), Is.EqualTo(Enumerable.Range(1, 8).Select(i => i.ToString(CultureInfo.InvariantCulture))),
            "the header and trials 1 to 8, each once");
        var violations = StraceCheck.Violations(File.ReadAllLines(trace), dir,
            lines.Where(l => l.StartsWith("ack ", StringComparison.Ordinal)).Select(a => Path.Combine(dir, a.StartsWith("ack trial ", StringComparison.Ordinal) ? "trials.csv" : "responses.csv")).ToList());
        Assert.That(violations, Is.Empty, "every acknowledged answer synced, the retried one included");
    }

    static string RequireStrace()
    {
        if (!OperatingSystem.IsLinux()) Assert.Ignore("the syscall-order test runs on Linux (strace)");
        string? found = Which("strace");
        if (found == null && IsRoot())
        {
            // As .ci/run does: Debian's package, quietly.
            Run("apt-get", "install", "-y", "-qq", "strace");
            found = Which("strace");
        }
        if (found == null) Assert.Ignore("strace is not installed and could not be installed (apt-get install strace as root): the syscall order is not checked");
        return found!;
    }

    // ---------------------------------------------------------------------------------------------- kills

    [Test]
    public void KilledAtRandomInstantsTheFilesParseResumeAndHoldEveryAcknowledgedAnswerOnce()
    {
        if (!OperatingSystem.IsLinux() && !OperatingSystem.IsMacOS()) Assert.Ignore("SIGKILL: Unix");
        int kills = int.TryParse(Environment.GetEnvironmentVariable("PSEUDOHAPTIC_KILLS"), out int k) && k > 0 ? k : 20;
        int seed = int.TryParse(Environment.GetEnvironmentVariable("PSEUDOHAPTIC_KILL_SEED"), out int s) ? s : 35;
        var rng = new Random(seed);
        var catalog = CatalogOfTheChild();
        string trials = Path.Combine(_dir, "trials.csv"), responses = Path.Combine(_dir, "responses.csv");
        var acked = new List<string>();          // "trials.csv|row" or "responses.csv|row"
        int participant = 1, midSession = 0, finished = 0, leftByKills = 0;
        var watch = Stopwatch.StartNew();
        for (int kill = 0; kill < kills; kill++)
        {
            string id = "P" + participant.ToString(CultureInfo.InvariantCulture);
            int ackedTrials = acked.Count(a => a.StartsWith("trials.csv|" + id + ",", StringComparison.Ordinal));
            int ackedItems = acked.Count(a => a.StartsWith("responses.csv|" + id + ",", StringComparison.Ordinal));
            // What the last kill left half-written: the session removes it when it resumes (or starts) in the folder.
            string[] stale = StaleTemporaries();
            leftByKills += stale.Length;
            using var child = new Child(_dir, id);
            var (p, lines, stderr) = (child.Process, child.Lines, child.Stderr);
            bool started = child.Ready.Wait(60_000) || p.HasExited;
            Assert.That(started, Is.True, "kill " + kill + ": the child did not start");
            if (!p.HasExited)
                Assert.That(stale.Where(File.Exists), Is.Empty, "kill " + kill + ": the temporary files the last kill left are removed once the session has begun");
            // A seeded instant, mostly within the session (its 40 answers take some 100-300 ms here), some beyond it.
            Thread.Sleep(rng.Next(0, 150));
            try { p.Kill(); } catch (InvalidOperationException) { } // SIGKILL on Unix; it may have finished
            p.WaitForExit(); // and its standard output read to the end
            string[] got;
            lock (lines) got = lines.ToArray();
            Assert.That(got.Length, Is.GreaterThan(0), "kill " + kill + ": " + stderr.Result);
            string[] head = got[0].Split(' ');
            Assert.That(head[0], Is.EqualTo("ready"), "kill " + kill + ": " + stderr.Result);
            Assert.That(int.Parse(head[1], CultureInfo.InvariantCulture), Is.GreaterThanOrEqualTo(ackedTrials), "kill " + kill + ": resumed before an acknowledged trial");
            Assert.That(int.Parse(head[2], CultureInfo.InvariantCulture), Is.GreaterThanOrEqualTo(ackedItems), "kill " + kill + ": resumed before an acknowledged item");
            foreach (string line in got)
            {
                if (line.StartsWith("ack trial ", StringComparison.Ordinal)) acked.Add("trials.csv|" + line["ack trial ".Length..]);
                else if (line.StartsWith("ack item ", StringComparison.Ordinal)) acked.Add("responses.csv|" + line["ack item ".Length..]);
            }
            if (got.Contains("done")) { participant++; finished++; }
            else midSession++;

            // After every kill: both files parse as psychometric and score read them, and hold every acknowledged answer once.
            string trialsText = File.Exists(trials) ? File.ReadAllText(trials) : TrialsCsv.Header + "\n";
            string responsesText = File.Exists(responses) ? File.ReadAllText(responses) : ResponsesCsv.Header + "\n";
            Assert.DoesNotThrow(() => TrialsCsv.Read(new StringReader(trialsText), trials), "kill " + kill);
            Assert.DoesNotThrow(() => ResponsesCsv.Parse(responsesText, responses, catalog), "kill " + kill);
            var rows = trialsText.Split('\n').Select(r => "trials.csv|" + r).Concat(responsesText.Split('\n').Select(r => "responses.csv|" + r))
                .GroupBy(r => r).ToDictionary(g => g.Key, g => g.Count());
            foreach (string a in acked)
                Assert.That(rows.GetValueOrDefault(a), Is.EqualTo(1), "kill " + kill + ": acknowledged " + a);
            var trialKeys = trialsText.Split('\n').Skip(1).Where(r => r.Length > 0).Select(r => string.Join(",", r.Split(',').Take(3)));
            Assert.That(trialKeys, Is.Unique, "kill " + kill + ": a trial answered twice");
        }
        // The final resume, not killed: it finishes its participant, and nothing half-written is left in the folder.
        int beforeFinal = StaleTemporaries().Length;
        leftByKills += beforeFinal;
        string lastId = "P" + participant.ToString(CultureInfo.InvariantCulture);
        using (var final = new Child(_dir, lastId))
        {
            Assert.That(final.Process.WaitForExit(120_000), Is.True, "the final resume hung");
            final.Process.WaitForExit(); // its standard output read to the end
            string[] got;
            lock (final.Lines) got = final.Lines.ToArray();
            Assert.That(final.Process.ExitCode, Is.Zero, final.Stderr.Result);
            Assert.That(got, Does.Contain("done"), "the final resume finished " + lastId);
        }
        string[] left = Directory.GetFiles(_dir, ".ph*.tmp").Select(Path.GetFileName).ToArray()!;
        string trialsAfter = File.ReadAllText(trials), responsesAfter = File.ReadAllText(responses);
        foreach (string a in acked)
            Assert.That((a.StartsWith("trials.csv|", StringComparison.Ordinal) ? trialsAfter : responsesAfter).Split('\n').Count(r => r == a[(a.IndexOf('|') + 1)..]),
                Is.EqualTo(1), "after the final resume: acknowledged " + a);
        TestContext.Progress.WriteLine(string.Format(CultureInfo.InvariantCulture,
            "kill test (seed {0}): {1} kills in {2:F0} s, {3} mid-session and {4} after a finished session; {5} acknowledged answers of {6} participants, each in its file exactly once; {7} temporary files left by kills, each removed when the next session began; {8} left after the final resume",
            seed, kills, watch.Elapsed.TotalSeconds, midSession, finished, acked.Count, participant, leftByKills, left.Length));
        Assert.That(left, Is.Empty, "no temporary file is left once the final resume has finished");
        Assert.That(midSession, Is.GreaterThanOrEqualTo(kills / 4), "kills must land inside sessions, or the test shows little");
        Assert.That(acked.Count, Is.GreaterThan(kills), "answers were acknowledged between kills");
    }

    /// <summary>AtomicFile's temporary files in the test's folder (exactly its pattern, as the session removes them).</summary>
    string[] StaleTemporaries() => Directory.GetFiles(_dir, ".ph*.tmp").Where(f => AtomicFile.IsTemporaryName(Path.GetFileName(f))).ToArray();

    /// <summary>A participant child answering into <c>dir</c>, its standard output collected line by line.</summary>
    sealed class Child : IDisposable
    {
        public readonly Process Process;
        public readonly List<string> Lines = new();
        public readonly ManualResetEventSlim Ready = new(false);
        public readonly Task<string> Stderr;

        public Child(string dir, string id)
        {
            var info = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in new[] { ChildDll, "participant", dir, id, "7", "8" }) info.ArgumentList.Add(a);
            Process = new Process { StartInfo = info };
            Process.OutputDataReceived += (_, e) =>
            {
                if (e.Data == null) return;
                lock (Lines) Lines.Add(e.Data);
                if (e.Data.StartsWith("ready ", StringComparison.Ordinal)) Ready.Set();
            };
            Process.Start();
            Process.BeginOutputReadLine();
            Stderr = Process.StandardError.ReadToEndAsync();
        }

        public void Dispose()
        {
            // (Ready is not disposed: the output reader may still set it while a killed child's pipe drains.)
            try { if (!Process.HasExited) Process.Kill(); } catch (InvalidOperationException) { }
            Process.WaitForExit(10_000);
            Process.Dispose();
        }
    }

    static QuestionnaireCatalog CatalogOfTheChild()
    {
        var a = new Questionnaire("part-a", "Part A", 1, 7, Enumerable.Range(1, 5).Select(i => new QuestionnaireItem(i, "Item " + i, i == 3)).ToArray());
        var b = new Questionnaire("part-b", "Part B", 1, 10, Enumerable.Range(1, 3).Select(i => new QuestionnaireItem(i, "Item " + i, false)).ToArray());
        return new QuestionnaireCatalog(new[] { a, b });
    }

    // ---------------------------------------------------------------------------------------------- full disk, read-only

    string? _mounted;

    /// <summary>A small tmpfs at a fresh folder (root only; else the test is ignored with the reason).</summary>
    string Mount(string options)
    {
        if (!OperatingSystem.IsLinux()) Assert.Ignore("tmpfs mounts: Linux");
        if (!IsRoot()) Assert.Ignore("mounting a small tmpfs needs root; a full disk and a read-only folder are not tested here");
        string at = Path.Combine(_dir, "mnt");
        Directory.CreateDirectory(at);
        var (code, output) = Run("mount", "-t", "tmpfs", "-o", options, "tmpfs", at);
        if (code != 0) Assert.Ignore("mount -t tmpfs refused (" + output.Trim() + "): a full disk and a read-only folder are not tested here");
        _mounted = at;
        return at;
    }

    static string[] Temporaries(string dir) => Directory.GetFiles(dir, ".ph*").Select(Path.GetFileName).ToArray()!;

    [Test]
    public void OnAFullDiskTheAnswerIsKeptTheErrorSaidNothingHalfWrittenLeftAndItIsWrittenOnceThereIsRoom()
    {
        string disk = Mount("size=256k");
        string path = Path.Combine(disk, "responses.csv");
        double now = 0;
        var model = new QuestionnairePanelModel(saver: new SaveQueue(background: false, retrySeconds: 1, clock: () => now));
        Assert.That(model.Begin(CatalogOfTheChild(), "P1", path, null), Is.True, model.Error);
        Assert.That(model.Answer(4), Is.True, model.Error);
        string before = File.ReadAllText(path);

        // Fill the disk to the last byte.
        string filler = Path.Combine(disk, "filler");
        var fill = new FileStream(filler, FileMode.Create, FileAccess.Write, FileShare.None, bufferSize: 0); // unbuffered
        try
        {
            var block = new byte[4096];
            try { while (true) fill.Write(block, 0, block.Length); }
            catch (IOException) { }
            var one = new byte[1];
            try { while (true) fill.Write(one, 0, 1); }
            catch (IOException) { }
        }
        finally
        {
            fill.Dispose();
        }

        Assert.That(model.Answer(5), Is.False, "not saved");
        Assert.That(model.Error, Does.Contain("space").IgnoreCase, "the error says why");
        Assert.That(model.View(0.6f, 0.004f).Message, Does.Contain("could not be saved"), "the headset says so");
        Assert.That(model.IsSaving, Is.True, "the answer is kept");
        Assert.That(model.Session.StepIndex, Is.EqualTo(1), "not acknowledged: the item stays");
        Assert.That(File.ReadAllText(path), Is.EqualTo(before), "the file as it was");
        Assert.That(Temporaries(disk), Is.Empty, "no half-written temporary file");
        now = 1;
        Assert.That(model.Update(), Is.False, "still full: tried again, failed again");
        Assert.That(Temporaries(disk), Is.Empty);

        File.Delete(filler);
        now = 2;
        Assert.That(model.Update(), Is.True);
        Assert.That(model.Error, Is.Null);
        Assert.That(File.ReadAllLines(path), Is.EqualTo(new[] { ResponsesCsv.Header, "P1,part-a,1,4", "P1,part-a,2,5" }), "written once");
        Assert.That(Temporaries(disk), Is.Empty);
    }

    [Test]
    public void InAReadOnlyFolderTheAnswerIsKeptTheErrorSaidNothingLeftAndItIsWrittenOnceItIsWritableAgain()
    {
        // Root ignores permission bits (chmod), so the folder is a tmpfs remounted read-only.
        string folder = Mount("size=256k");
        string path = Path.Combine(folder, "trials.csv");
        double now = 0;
        var model = new DiscriminationTaskModel(saver: new SaveQueue(background: false, retrySeconds: 1, clock: () => now));
        var settings = new DiscriminationSettings { Procedure = DiscriminationProcedure.ConstantStimuli, StandardKg = 1, ComparisonKg = new[] { 0.8, 1.2 }, Repetitions = 2, Seed = 3 };
        Assert.That(model.Begin(true, settings, "P1", "", path), Is.True, model.Error);
        model.NoteLift(true, false);
        model.NoteLift(false, true);
        Assert.That(model.Answer(PairSide.Left, false), Is.True, model.Error);
        string before = File.ReadAllText(path);
        Assert.That(Run("mount", "-o", "remount,ro", folder).code, Is.Zero);

        model.NoteLift(true, false);
        model.NoteLift(false, true);
        Assert.That(model.Answer(PairSide.Right, false), Is.False);
        Assert.That(model.Error, Does.StartWith(DiscriminationTaskModel.NotSavedPrefix).And.Contain("Read-only").IgnoreCase);
        Assert.That(model.DisplayText(), Is.EqualTo(model.Error), "the headset says so");
        Assert.That(model.IsSaving, Is.True, "the answer is kept");
        Assert.That(model.Session.AnsweredCount, Is.EqualTo(1));
        Assert.That(File.ReadAllText(path), Is.EqualTo(before));
        Assert.That(Temporaries(folder), Is.Empty);

        Assert.That(Run("mount", "-o", "remount,rw", folder).code, Is.Zero);
        now = 1;
        Assert.That(model.Update(), Is.True);
        Assert.That(model.Error, Is.Null);
        string[] lines = File.ReadAllLines(path);
        Assert.That(lines, Has.Length.EqualTo(3), "the header and two answers, each once");
        Assert.That(lines[2].Split(',')[2], Is.EqualTo("2"), "the kept answer is trial 2's");
        Assert.That(model.Saver.Writes, Is.EqualTo(2));
    }

    // ---------------------------------------------------------------------------------------------- helpers

    static bool IsRoot() => OperatingSystem.IsLinux() && File.ReadAllLines("/proc/self/status").Any(l => Regex.IsMatch(l, @"^Uid:\s+0\s"));

    static string? Which(string name)
    {
        foreach (string dir in (Environment.GetEnvironmentVariable("PATH") ?? "/usr/bin:/bin").Split(':'))
        {
            string candidate = Path.Combine(dir, name);
            if (File.Exists(candidate)) return candidate;
        }
        return null;
    }

    static (int code, string output) Run(string file, params string[] args)
    {
        try
        {
            var info = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in args) info.ArgumentList.Add(a);
            using var p = Process.Start(info)!;
            var err = p.StandardError.ReadToEndAsync();
            string output = p.StandardOutput.ReadToEnd();
            if (!p.WaitForExit(300_000)) { p.Kill(); return (-1, "timed out"); }
            return (p.ExitCode, output + err.Result);
        }
        catch (System.ComponentModel.Win32Exception e)
        {
            return (-1, e.Message);
        }
    }
}

/// <summary>
/// Reads an strace -f log (fsync, fdatasync, rename*, link*, openat) and checks, for each acknowledgement mark (an
/// openat of DIR/.ack-N failing with ENOENT), that the last rename (or link) onto its file before the mark moved a
/// temporary file that had been fsynced (or fdatasynced) after it was created and before the rename, and that the file's
/// folder was fsynced after the rename and before the mark.
/// </summary>
public static class StraceCheck
{
    static readonly Regex Complete = new(@"^(\d+)\s+(\w+)\((.*)\)\s+=\s+(-?\d+)");
    static readonly Regex Unfinished = new(@"^(\d+)\s+(\w+)\((.*) <unfinished \.\.\.>$");
    static readonly Regex Resumed = new(@"^(\d+)\s+<\.\.\. (\w+) resumed>(.*)\)\s+=\s+(-?\d+)");
    static readonly Regex Quoted = new("\"((?:[^\"\\\\]|\\\\.)*)\"");

    public sealed record Call(string Name, string Args, long Result);

    public static List<Call> Parse(IEnumerable<string> lines)
    {
        var calls = new List<Call>();
        var pending = new Dictionary<string, (string name, string args)>();
        foreach (string line in lines)
        {
            Match m;
            if ((m = Complete.Match(line)).Success)
                calls.Add(new Call(m.Groups[2].Value, m.Groups[3].Value, long.Parse(m.Groups[4].Value, CultureInfo.InvariantCulture)));
            else if ((m = Unfinished.Match(line)).Success)
                pending[m.Groups[1].Value] = (m.Groups[2].Value, m.Groups[3].Value);
            else if ((m = Resumed.Match(line)).Success && pending.Remove(m.Groups[1].Value, out var start))
                calls.Add(new Call(start.name, start.args + m.Groups[3].Value, long.Parse(m.Groups[4].Value, CultureInfo.InvariantCulture)));
        }
        return calls;
    }

    public static List<string> Violations(IEnumerable<string> trace, string dir, IReadOnlyList<string> ackedFiles)
    {
        var calls = Parse(trace);
        var fdPath = new Dictionary<long, string>();
        // Events in completion order: ("create", temp) ("sync", path) ("move", src, dst) ("ack", n)
        var events = new List<(string kind, string a, string b)>();
        foreach (var c in calls)
        {
            var paths = Quoted.Matches(c.Args).Select(q => q.Groups[1].Value).ToArray();
            switch (c.Name)
            {
                case "openat":
                    if (paths.Length == 0) break;
                    if (c.Result >= 0)
                    {
                        fdPath[c.Result] = paths[0];
                        if (c.Args.Contains("O_CREAT", StringComparison.Ordinal)) events.Add(("create", paths[0], ""));
                    }
                    else if (Path.GetFileName(paths[0]).StartsWith(".ack-", StringComparison.Ordinal) && Path.GetDirectoryName(paths[0]) == dir)
                        events.Add(("ack", Path.GetFileName(paths[0])[".ack-".Length..], ""));
                    break;
                case "fsync":
                case "fdatasync":
                    if (c.Result == 0 && long.TryParse(c.Args.Split(',')[0].Trim(), out long fd) && fdPath.TryGetValue(fd, out string? synced))
                        events.Add(("sync", synced, ""));
                    break;
                case "rename":
                case "renameat":
                case "renameat2":
                case "link":
                case "linkat":
                    if (c.Result == 0 && paths.Length >= 2) events.Add(("move", paths[0], paths[1]));
                    break;
            }
        }
        var violations = new List<string>();
        int acks = 0;
        for (int i = 0; i < events.Count; i++)
        {
            if (events[i].kind != "ack") continue;
            if (acks >= ackedFiles.Count) { violations.Add("mark " + events[i].a + ": more marks than acknowledgements"); continue; }
            string target = ackedFiles[acks++];
            string label = "acknowledgement " + acks + " (" + Path.GetFileName(target) + ")";
            int move = -1;
            for (int j = i - 1; j >= 0; j--)
                if (events[j].kind == "move" && events[j].b == target) { move = j; break; }
            if (move < 0) { violations.Add(label + ": no rename onto the file before it"); continue; }
            string temp = events[move].a;
            int created = -1;
            for (int j = move - 1; j >= 0; j--)
                if (events[j].kind == "create" && events[j].a == temp) { created = j; break; }
            bool dataSynced = false;
            for (int j = created + 1; j < move; j++)
                if (events[j].kind == "sync" && events[j].a == temp) dataSynced = true;
            if (!dataSynced) violations.Add(label + ": the temporary file " + Path.GetFileName(temp) + " was not fsynced before its rename");
            string folder = Path.GetDirectoryName(target)!;
            bool folderSynced = false;
            for (int j = move + 1; j < i; j++)
                if (events[j].kind == "sync" && events[j].a.TrimEnd('/') == folder) folderSynced = true;
            if (!folderSynced) violations.Add(label + ": its folder not fsynced after the rename and before the acknowledgement");
        }
        if (acks != ackedFiles.Count) violations.Add(ackedFiles.Count + " acknowledgements but " + acks + " marks in the trace");
        return violations;
    }
}
