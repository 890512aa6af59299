using System.CommandLine;
using System.CommandLine.Help;
using System.CommandLine.Invocation;
using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;

// pseudohaptic: headless tools around the weight solver. Each command returns its exit code; errors are one
// line on stderr, "pseudohaptic COMMAND: …", exit code 2 for usage and input errors, 1 for I/O.
return Cli.Run(args);

namespace Kosmos.PseudoHaptic.Cli
{
    public static class Cli
    {
        /// <summary>Exit codes, as README "Exit codes" documents them.</summary>
        public const int Success = 0, InputOutputError = 1, UsageError = 2;

        /// <summary>
        /// Set to a file name, the process writes its peak resident memory there when it ends (Linux: VmHWM of
        /// /proc/self/status, in kB). The tools' tests read it to bound every command's memory; it changes nothing else.
        /// </summary>
        public const string PeakMemoryVariable = "PSEUDOHAPTIC_PEAK_RSS_FILE";

        /// <summary>Every command, in the order help lists them (made anew for each run: a command belongs to one root).</summary>
        public static IReadOnlyList<CliCommand> Define() => new[]
        {
            Commands.DemoCommand.Define(),
            Commands.ReplayCommand.Define(),
            Commands.ProfilesCommand.Define(),
            Commands.TuneCommand.Define(),
            Commands.PersonalizationCommand.Define(),
            Commands.AccuracyCommand.Define(),
            ScoreCommand.Define(),
            ReportCommand.Define(),
            PsychometricCommand.Define(),
            CompareCommand.Define(),
            CompletionCommand.Define(),
            Commands.UnityPackageCommand.Define(),
        };

        public static int Run(string[] args)
        {
            PeakMemory.ReportAtExit(Environment.GetEnvironmentVariable(PeakMemoryVariable));
            var root = Root(Define());
            // A path that starts with '@' is a path, not a response file.
            var result = root.Parse(args, new ParserConfiguration { ResponseFileTokenReplacer = null });
            string who = result.CommandResult.Command is RootCommand ? "pseudohaptic" : "pseudohaptic " + result.CommandResult.Command.Name;
            if (args.Length == 0)
            {
                // No command: the overview, on standard error since nothing was done (exit 2).
                result = root.Parse(new[] { "--help" });
                result.Invoke(new InvocationConfiguration { Output = Console.Error, Error = Console.Error });
                return UsageError;
            }
            if (result.Errors.Count > 0 && result.Action is ParseErrorAction or null)
            {
                Console.Error.WriteLine($"{who}: {Messages.OneLine(ParseErrors.Describe(result))} (see '{who} --help')");
                return UsageError;
            }
            try
            {
                return result.Invoke(new InvocationConfiguration { Output = Console.Out, Error = Console.Error, EnableDefaultExceptionHandler = false });
            }
            catch (CliException e)
            {
                Console.Error.WriteLine($"{who}: {Messages.OneLine(e.Message)}");
                return e.ExitCode;
            }
            catch (Kosmos.PseudoHaptic.Evaluation.EvaluationFormatException e)
            {
                Console.Error.WriteLine($"{who}: {Messages.OneLine(e.Message)}");
                return UsageError;
            }
            catch (OperationCanceledException)
            {
                return 130; // a signal arrived; its handler removed the temporary files and ends the process
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                Console.Error.WriteLine($"{who}: {Messages.Reason(e)}");
                return InputOutputError;
            }
        }

        /// <summary>The tool's root command: every command, --help, --version and the [suggest] directive completion uses.</summary>
        public static RootCommand Root(IReadOnlyList<CliCommand> commands)
        {
            var root = new RootCommand("pseudohaptic: pseudo-haptic weight (Son et al., Electronics 2022) without a headset. Run 'pseudohaptic COMMAND --help' for a command's options, units, defaults and examples.");
            foreach (var c in commands) root.Subcommands.Add(c.Command);
            var help = root.Options.OfType<HelpOption>().Single();
            if (help.Action is HelpAction standard) help.Action = new HelpWithExamples(standard, commands);
            return root;
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
