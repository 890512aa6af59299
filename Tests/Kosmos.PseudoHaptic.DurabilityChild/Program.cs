using System.Diagnostics;
using System.Globalization;
using Kosmos.PseudoHaptic;
using Kosmos.PseudoHaptic.Evaluation;

// The child process of DurabilityTests (issue 35). Modes:
//   participant DIR PARTICIPANT SEED [REPETITIONS] [--marker]
//       answers a constant-stimuli plan (4 comparisons x REPETITIONS, default 4) into DIR/trials.csv, then a
//       questionnaire (part-a: 5 items on 1-7, part-b: 3 items on 1-10) into DIR/responses.csv, through the package's
//       DiscriminationTaskModel and QuestionnairePanelModel sharing one background SaveQueue, as the headset does.
//       Prints "ready TRIALS ITEMS" (answers already in the files), then for every acknowledged answer
//       "ack trial ROW" or "ack item ROW" (the exact CSV row), then "done". With --marker, before printing an
//       acknowledgement it opens DIR/.ack-N (which does not exist), a mark in an strace log. An answer whose write
//       failed prints "error trial MESSAGE" or "error item MESSAGE" (once per failure) and is tried again.
//   atomic DIR
//       AtomicFile's other ways in, each followed by a mark (an open of DIR/.ack-N, which does not exist): creates
//       DIR/made/deeper (both missing), writes DIR/made/deeper/with.csv through WriteWith (its writer does not sync),
//       then DIR/made/deeper/text.csv through WriteAllText.
//   sync-fault DIR [--close-stdin]
//       writes DIR/answer.csv twice through AtomicFile.WriteAllText ("first", then "second"), printing after each
//       "ok DIRECTORYSYNC" or "error MESSAGE" and "file CONTENT" ("none" if there is no file), then "temporaries N".
//       Run under strace's fault injection (fsync 1: the temporary file's, fsync 2: the folder's). With
//       --close-stdin, standard input is closed before the second write, whose file and folder then open as descriptor 0.
//   recorder DIR HOLDS
//       records HOLDS holds of 30 frames through the package's SessionLog (session P1, one background SaveQueue, as the
//       SessionRecorder does); for each hold its HoldWritten event opens DIR/.ack-N (a mark in an strace log) and
//       prints "ack hold FILE". Then "done".
//   bench DIR ANSWERS
//       times ANSWERS answers written one by one as a session writes them (the whole growing file each time),
//       synced (AtomicFile.Durable) and unsynced, and prints one line per mode.
// Exit codes: 0 done, 2 usage, 3 the session could not begin (the reason on standard error).
namespace Kosmos.PseudoHaptic.DurabilityChild;

static class Program
{
    static int Main(string[] args)
    {
        // For DurabilityTests' check that its strace check can fail: the same writer without any sync.
        if (Environment.GetEnvironmentVariable("PSEUDOHAPTIC_UNSYNCED") == "1") AtomicFile.Durable = false;
        if (args.Length >= 4 && args[0] == "participant")
            return Participant(args[1], args[2], int.Parse(args[3], CultureInfo.InvariantCulture),
                args.Length >= 5 && args[4] != "--marker" ? int.Parse(args[4], CultureInfo.InvariantCulture) : 4, args.Contains("--marker"));
        if (args.Length == 2 && args[0] == "atomic") return Atomic(args[1]);
        if (args.Length >= 2 && args[0] == "sync-fault") return SyncFault(args[1], args.Contains("--close-stdin"));
        if (args.Length == 3 && args[0] == "recorder") return Recorder(args[1], int.Parse(args[2], CultureInfo.InvariantCulture));
        if (args.Length == 3 && args[0] == "bench") return Bench(args[1], int.Parse(args[2], CultureInfo.InvariantCulture));
        Console.Error.WriteLine("usage: participant DIR PARTICIPANT SEED [REPETITIONS] [--marker] | atomic DIR | sync-fault DIR [--close-stdin] | recorder DIR HOLDS | bench DIR ANSWERS");
        return 2;
    }

    public static DiscriminationSettings Settings(int seed, int repetitions) => new DiscriminationSettings
    {
        Procedure = DiscriminationProcedure.ConstantStimuli,
        StandardKg = 1.0,
        ComparisonKg = new[] { 0.8, 0.9, 1.1, 1.2 },
        Repetitions = repetitions,
        Seed = seed,
    };

    public static QuestionnaireCatalog Catalog()
    {
        var a = new Questionnaire("part-a", "Part A", 1, 7, Enumerable.Range(1, 5).Select(i => new QuestionnaireItem(i, "Item " + i, i == 3)).ToArray());
        var b = new Questionnaire("part-b", "Part B", 1, 10, Enumerable.Range(1, 3).Select(i => new QuestionnaireItem(i, "Item " + i, false)).ToArray());
        return new QuestionnaireCatalog(new[] { a, b });
    }

    /// <summary>A seeded choice for (participant, key): the same answer however often the child is restarted.</summary>
    static int Choice(int seed, string participant, string key, int n)
    {
        unchecked
        {
            uint h = 2166136261u ^ (uint)seed;
            foreach (char c in participant + "|" + key) h = (h ^ c) * 16777619u;
            return (int)(h % (uint)n);
        }
    }

    static int Participant(string dir, string participant, int seed, int repetitions, bool marker)
    {
        var stdout = Console.Out;
        int acks = 0;
        void Ack(string what)
        {
            if (marker)
                try { using (File.OpenRead(Path.Combine(dir, ".ack-" + (++acks).ToString(CultureInfo.InvariantCulture)))) { } }
                catch (FileNotFoundException) { }
            stdout.WriteLine("ack " + what);
            stdout.Flush();
        }

        var saver = new SaveQueue(background: true, retrySeconds: 0.05);
        var task = new DiscriminationTaskModel(0, 0, saver);
        var panel = new QuestionnairePanelModel(0, 0, saver);
        if (!task.Begin(true, Settings(seed, repetitions), participant, "", Path.Combine(dir, "trials.csv")))
        {
            Console.Error.WriteLine("trials: " + task.Error);
            return 3;
        }
        if (!panel.Begin(Catalog(), participant, Path.Combine(dir, "responses.csv"), null))
        {
            Console.Error.WriteLine("responses: " + panel.Error);
            return 3;
        }
        stdout.WriteLine("ready " + task.Session.AnsweredCount.ToString(CultureInfo.InvariantCulture) + " " + panel.Session.AnsweredCount.ToString(CultureInfo.InvariantCulture));
        stdout.Flush();

        // What an acknowledgement names is set before the answer is given: the write can return, and Answer's own
        // pump deliver its acknowledgement, before Answer returns (then Current is already the next trial).
        string pending = null;
        Trial answered = null;
        task.Saved += () => Ack("trial " + TrialsCsv.FormatRow(answered));
        panel.Answered += s => Ack("item " + pending);
        while (!task.Session.IsFinished)
        {
            task.NoteLift(true, false);
            task.NoteLift(false, true);
            Trial trial = task.Session.Current;
            var side = Choice(seed, participant, "trial " + trial.Index, 2) == 0 ? PairSide.Left : PairSide.Right;
            answered = trial;
            if (!task.Answer(side, false) && !task.IsSaving) throw new InvalidOperationException("not taken: " + task.Error);
            string said = null;
            while (task.IsSaving)
            {
                said = SayError("trial", task.Error, said);
                Thread.Sleep(1); // a frame
                task.Update();
            }
        }
        while (!panel.Session.IsFinished)
        {
            Questionnaire q = panel.Session.CurrentQuestionnaire;
            QuestionnaireItem item = panel.Session.CurrentItem;
            int value = q.ScaleMin + Choice(seed, participant, q.Id + " " + item.Number, q.ScaleMax - q.ScaleMin + 1);
            pending = ResponsesCsv.FormatRow(new Response(participant, q.Id, item.Number, value));
            if (!panel.Answer(value) && !panel.IsSaving) throw new InvalidOperationException("not taken: " + panel.Error);
            string said = null;
            while (panel.IsSaving)
            {
                said = SayError("item", panel.Error, said);
                Thread.Sleep(1);
                panel.Update();
            }
        }
        stdout.WriteLine("done");
        stdout.Flush();
        return 0;
    }

    /// <summary>Prints "error WHAT MESSAGE" when the shown error is a new one; returns the error now shown.</summary>
    static string SayError(string what, string error, string said)
    {
        if (error != null && error != said)
        {
            Console.Out.WriteLine("error " + what + " " + error);
            Console.Out.Flush();
        }
        return error;
    }

    static int SyncFault(string dir, bool closeStdin)
    {
        string path = Path.Combine(dir, "answer.csv");
        foreach (string text in new[] { "first", "second" })
        {
            // After the first write, when the runtime has loaded what a write needs (its loader would take descriptor 0).
            if (closeStdin && text == "second") CloseDescriptor(0);
            try
            {
                AtomicFile.WriteAllText(path, text);
                Console.WriteLine("ok " + AtomicFile.DirectorySync);
            }
            catch (IOException e)
            {
                Console.WriteLine("error " + e.Message);
            }
            Console.WriteLine("file " + (File.Exists(path) ? File.ReadAllText(path) : "none"));
        }
        Console.WriteLine("temporaries " + Directory.GetFiles(dir, ".ph*").Length.ToString(CultureInfo.InvariantCulture));
        return 0;
    }

    [System.Runtime.InteropServices.DllImport("libc", EntryPoint = "close")]
    static extern int CloseDescriptor(int fd);

    static int Recorder(string dir, int holds)
    {
        int acked = 0;
        var log = new SessionLog(saver: new SaveQueue(background: true, retrySeconds: 0.05)) { Folder = dir, SessionId = "P1" };
        log.HoldWritten += file =>
        {
            try { using (File.OpenRead(Path.Combine(dir, ".ack-" + (++acked).ToString(CultureInfo.InvariantCulture)))) { } }
            catch (FileNotFoundException) { }
            Console.Out.WriteLine("ack hold " + file);
            Console.Out.Flush();
        };
        var solver = new WeightSolver(WeightModel.FromMass(0.5));
        const double dt = 1 / 90.0;
        for (int h = 0; h < holds; h++)
        {
            object key = new object();
            var grab = new HandSample(1.0);
            solver.BeginHold(1.0, 1.0);
            log.Began(key, "cube", solver, in grab, h);
            for (int i = 1; i <= 30; i++)
            {
                var hand = new HandSample(1.0 + 0.01 * i);
                solver.Step(in hand, dt);
                log.Stepped(key, solver, in hand, dt);
            }
            log.Ended(key);
            while (acked <= h)
            {
                Thread.Sleep(1); // a frame
                log.Pump();
            }
        }
        log.Drain();
        Console.WriteLine("done");
        return 0;
    }

    static int Atomic(string dir)
    {
        int marks = 0;
        void Mark()
        {
            try { using (File.OpenRead(Path.Combine(dir, ".ack-" + (++marks).ToString(CultureInfo.InvariantCulture)))) { } }
            catch (FileNotFoundException) { }
        }
        string deeper = Path.Combine(dir, "made", "deeper");
        AtomicFile.CreateDirectory(deeper);
        Mark();
        AtomicFile.WriteWith(Path.Combine(deeper, "with.csv"), temp => File.WriteAllText(temp, "with\n"));
        Mark();
        AtomicFile.WriteAllText(Path.Combine(deeper, "text.csv"), "text\n");
        Mark();
        Console.WriteLine("done");
        return 0;
    }

    static int Bench(string dir, int answers)
    {
        Directory.CreateDirectory(dir);
        foreach (bool durable in new[] { true, false })
        {
            string path = Path.Combine(dir, durable ? "synced.csv" : "unsynced.csv");
            if (File.Exists(path)) File.Delete(path);
            var settings = new DiscriminationSettings
            {
                Procedure = DiscriminationProcedure.ConstantStimuli,
                StandardKg = 1.0,
                ComparisonKg = Enumerable.Range(1, 10).Select(i => 0.5 + 0.1 * i).ToArray(),
                Repetitions = (answers + 9) / 10,
                Seed = 1,
            };
            var session = settings.CreateSession("P1", "", path);
            var each = new double[answers];
            AtomicFile.Durable = durable;
            var total = Stopwatch.StartNew();
            for (int i = 0; i < answers; i++)
            {
                session.NoteLift(PairSide.Left);
                session.NoteLift(PairSide.Right);
                long start = Stopwatch.GetTimestamp();
                session.Answer(i % 2 == 0 ? PairSide.Left : PairSide.Right);
                each[i] = Stopwatch.GetElapsedTime(start).TotalMilliseconds;
            }
            total.Stop();
            AtomicFile.Durable = true;
            Array.Sort(each);
            Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                "{0}: {1} answers in {2:F2} s; per answer mean {3:F3} ms, median {4:F3} ms, p95 {5:F3} ms, max {6:F3} ms (file at the end {7} bytes; folder synced: {8})",
                durable ? "synced" : "unsynced", answers, total.Elapsed.TotalSeconds, each.Average(), each[answers / 2],
                each[(int)(answers * 0.95)], each[answers - 1], new FileInfo(path).Length, durable ? AtomicFile.DirectorySync.ToString() : "no sync"));
        }
        return 0;
    }
}
