using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Cli.Commands;

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
              replay --trace IN.csv --out OUT.csv --mass-kg M [--standard-speed V] [--profile paper|paper-experiment|gain] [--grab-offset D]
              score  --responses R.csv --out S.csv [--questionnaires DIR]
                                                     score questionnaire responses
              report --scores S.csv --out DIR [--responses R.csv] [--questionnaires DIR] [--svg]
                                                     tables, statistics and charts of scores
              accuracy [--trace FILE] [--lifts all|none] [--mass-kg M] [--long-minutes N] [--csv OUT.csv] [--costs BENCH_RESULTS --chart OUT.png [--svg]]
                                                     accuracy of each estimator on Quest-like input (accuracy-vs-time.md)
            """;

        public static int Run(string[] args)
        {
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
                    _ => throw new CliException($"unknown command '{args[0]}'; expected demo, replay, score, report or accuracy"),
                };
            }
            catch (CliException e)
            {
                Console.Error.WriteLine("pseudohaptic: " + e.Message);
                return e.ExitCode;
            }
            catch (IOException e)
            {
                Console.Error.WriteLine("pseudohaptic: " + e.Message.ReplaceLineEndings(" "));
                return 1;
            }
            catch (UnauthorizedAccessException e)
            {
                Console.Error.WriteLine("pseudohaptic: " + e.Message.ReplaceLineEndings(" "));
                return 1;
            }
        }
    }
}
