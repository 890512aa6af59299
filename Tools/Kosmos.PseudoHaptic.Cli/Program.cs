using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Cli.Commands;
using Kosmos.PseudoHaptic.Cli.Files;

// pseudohaptic: headless tools around the weight solver. Each command returns its exit code; contract
// errors are one line on stderr and exit code 2.
return Cli.Run(args);

namespace Kosmos.PseudoHaptic.Cli
{
    public static class Cli
    {
        public const string Usage = """
            pseudohaptic — pseudo-haptic weight (Son et al., Electronics 2022) without a headset

              demo   [--out DIR] [--trace FILE] [--svg]
                                                     simulate the paper's scenes, write CSV + PNG (+ SVG), print a summary
              replay --trace IN.csv --out OUT.csv --mass-kg M [--standard-speed V] [--profile paper|paper-experiment|gain|xyz] [--grab-offset D] [--break-away D]
              score  --responses R.csv --out S.csv [--questionnaires DIR]
                                                     score questionnaire responses
              report --scores S.csv --out DIR [--responses R.csv] [--questionnaires DIR] [--svg]
                                                     tables, statistics and charts of scores
              psychometric --trials T.csv --out DIR [--lapse L] [--bootstrap N] [--seed S]
                                                     fit 2AFC answers: PSE, JND, Weber fraction, bootstrap CIs, charts
              compare --scores S.csv --out DIR       paired tests between conditions (t, Wilcoxon, Friedman, Holm)
              accuracy [--trace FILE] [--lifts all|none] [--mass-kg M] [--long-minutes N] [--csv OUT.csv] [--costs BENCH_RESULTS --chart OUT.png [--svg]]
                                                     accuracy of each estimator on Quest-like input (accuracy-vs-time.md)
            """;

        /// <summary>
        /// Set to a file name, the process writes its peak resident memory there when it ends (Linux: VmHWM of
        /// /proc/self/status, in kB). The tools' tests read it to bound every command's memory; it changes nothing else.
        /// </summary>
        public const string PeakMemoryVariable = "PSEUDOHAPTIC_PEAK_RSS_FILE";

        public static int Run(string[] args)
        {
            PeakMemory.ReportAtExit(Environment.GetEnvironmentVariable(PeakMemoryVariable));
            if (args.Length == 0 || args[0] is "-h" or "--help" or "help")
            {
                Console.Out.WriteLine(Usage);
                return args.Length == 0 ? 2 : 0;
            }
            var rest = args[1..];
            try
            {
                return args[0] switch
                {
                    "demo" => DemoCommand.Run(rest),
                    "replay" => ReplayCommand.Run(rest),
                    "score" => ScoreCommand.Run(rest),
                    "report" => ReportCommand.Run(rest),
                    "accuracy" => AccuracyCommand.Run(rest),
                    "psychometric" => PsychometricCommand.Run(rest),
                    "compare" => CompareCommand.Run(rest),
                    _ => throw new CliException($"unknown command '{args[0]}'; expected demo, replay, score, report, psychometric, compare or accuracy"),
                };
            }
            catch (CliException e)
            {
                Console.Error.WriteLine("pseudohaptic: " + Messages.OneLine(e.Message));
                return e.ExitCode;
            }
            catch (Kosmos.PseudoHaptic.Evaluation.EvaluationFormatException e)
            {
                Console.Error.WriteLine("pseudohaptic: " + Messages.OneLine(e.Message));
                return 2;
            }
            catch (OperationCanceledException)
            {
                return 130; // a signal arrived; its handler removed the temporary files and ends the process
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                Console.Error.WriteLine("pseudohaptic: " + Messages.Reason(e));
                return 1;
            }
        }
    }

    static class PeakMemory
    {
        static bool _registered;

        public static void ReportAtExit(string? file)
        {
            if (string.IsNullOrEmpty(file) || _registered || !File.Exists("/proc/self/status")) return;
            _registered = true;
            AppDomain.CurrentDomain.ProcessExit += (_, _) =>
            {
                try
                {
                    foreach (var line in File.ReadLines("/proc/self/status"))
                        if (line.StartsWith("VmHWM:", StringComparison.Ordinal))
                            File.WriteAllText(file, line["VmHWM:".Length..].Trim().Split(' ')[0] + "\n");
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException) { }
            };
        }
    }
}
