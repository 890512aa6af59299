using System.Text.RegularExpressions;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 25's command line: help on the tool and every command (every option, its unit or default, an example,
/// the exit codes), --version, completion, one error style ("pseudohaptic COMMAND: …", exit 2), progress only on a
/// terminal, and outputs checked before any work.
/// </summary>
public class CommandLineTests : CliTestFolder
{
    public CommandLineTests() : base("ph-cli-") { }

    static (int code, string stderr, string stdout) Run(params string[] args) => Capture(() => Cli.Cli.Run(args));

    static IEnumerable<string> CommandNames() => Cli.Cli.Define().Select(c => c.Name);

    [TestCaseSource(nameof(CommandNames))]
    public void Every_command_has_help_with_every_option_its_default_an_example_and_the_exit_codes(string name)
    {
        var command = Cli.Cli.Define().Single(c => c.Name == name);
        foreach (string help in new[] { "--help", "-h" })
        {
            var (code, stderr, stdout) = Run(name, help);
            Assert.That(code, Is.EqualTo(0), stderr);
            Assert.That(stderr, Is.Empty);
            foreach (var option in command.Command.Options.Where(o => o.Name.StartsWith("--", StringComparison.Ordinal) && o.Name != "--help"))
            {
                Assert.That(stdout, Does.Contain(option.Name), $"{name} {help} lists {option.Name}");
                Assert.That(option.Description, Is.Not.Empty, option.Name);
                bool flag = option.Arity.MaximumNumberOfValues == 0;
                if (!option.Required && !flag)
                    Assert.That(option.Description, Does.Contain("default").Or.Contain("also "), $"{name} {option.Name} says what happens without it");
            }
            Assert.That(stdout, Does.Contain("Examples").And.Contain("pseudohaptic " + name), "an example");
            Assert.That(stdout, Does.Contain("Exit codes: 0").And.Contain("1 a file").And.Contain("2 a usage"));
        }
        Assert.That(command.Examples, Is.Not.Empty);
        Assert.That(command.Examples, Has.All.StartWith("pseudohaptic " + name), "written as a user types them");
    }

    [Test]
    public void The_tool_has_help_version_and_a_list_of_its_commands()
    {
        var (code, _, stdout) = Run("--help");
        Assert.That(code, Is.EqualTo(0));
        foreach (var name in CommandNames()) Assert.That(stdout, Does.Contain("  " + name), name);
        (code, _, stdout) = Run("--version");
        Assert.That(code, Is.EqualTo(0));
        Assert.That(stdout.Trim(), Does.Match(@"^\d+\.\d+\.\d+"));
        var (none, stderr, output) = Run();
        Assert.That(none, Is.EqualTo(2), "no command is a usage error");
        Assert.That(output, Is.Empty);
        Assert.That(stderr, Does.Contain("replay"));
    }

    [TestCase(new[] { "frob" }, "pseudohaptic: unknown command 'frob'; expected demo, replay, profiles, tune, personalization, accuracy, score, report, psychometric, compare, completion, unity-package")]
    [TestCase(new[] { "--versoin" }, "pseudohaptic: unknown option '--versoin'; expected --help, --version or a command: demo, replay, profiles, tune, personalization, accuracy, score, report, psychometric, compare, completion, unity-package")]
    [TestCase(new[] { "demo", "--bogus" }, "pseudohaptic demo: unknown option '--bogus'; expected --out, --trace, --user, --svg")]
    [TestCase(new[] { "accuracy", "--bogus", "1" }, "pseudohaptic accuracy: unknown option '--bogus'; expected --trace, --lifts, --mass-kg, --standard-speed, --mocap, --long-minutes, --csv, --costs, --markdown, --chart, --svg")]
    [TestCase(new[] { "replay", "--trace", "a.csv", "--out", "b.csv" }, "pseudohaptic replay: option --mass-kg is required")]
    [TestCase(new[] { "replay", "--trace", "a.csv", "--out", "b.csv", "--mass-kg" }, "pseudohaptic replay: option --mass-kg needs a value")]
    [TestCase(new[] { "replay", "--trace", "a.csv", "--trace", "c.csv", "--out", "b.csv", "--mass-kg", "1" }, "pseudohaptic replay: option --trace is given twice")]
    [TestCase(new[] { "replay", "--trace", "a.csv", "--out", "b.csv", "--mass-kg", "heavy" }, "pseudohaptic replay: option --mass-kg: cannot parse 'heavy' as a number")]
    [TestCase(new[] { "replay", "--trace", "a.csv", "--out", "b.csv", "--mass-kg", "1", "--profile", "feather" }, "pseudohaptic replay: option --profile: unknown profile 'feather'")]
    [TestCase(new[] { "psychometric", "--trials", "t.csv", "--out", "o", "extra" }, "pseudohaptic psychometric: unexpected argument 'extra'")]
    [TestCase(new[] { "report", "--scores", "s.csv", "--out", "r", "--svg", "--svg" }, "pseudohaptic report: option --svg is given twice")]
    [TestCase(new[] { "completion", "fish" }, "pseudohaptic completion: ")]
    public void A_usage_error_is_one_line_naming_the_command_and_exits_2(string[] args, string message)
    {
        var (code, stderr, stdout) = Run(args);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.StartWith(message));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), stderr);
        Assert.That(stdout, Is.Empty);
    }

    [Test]
    public void Completion_prints_a_script_that_asks_the_tool_and_the_tool_completes_options_and_choices()
    {
        var (code, _, bash) = Run("completion", "bash");
        Assert.That(code, Is.EqualTo(0));
        Assert.That(bash, Does.Contain("complete -").And.Contain("[suggest:"));
        (code, _, string zsh) = Run("completion", "zsh");
        Assert.That(code, Is.EqualTo(0));
        Assert.That(zsh, Does.Contain("bashcompinit").And.Contain("[suggest:"));
        string line = "pseudohaptic replay --pro";
        (code, _, string options) = Run($"[suggest:{line.Length}]", line);
        Assert.That(code, Is.EqualTo(0));
        Assert.That(options.Split('\n', StringSplitOptions.RemoveEmptyEntries), Is.EqualTo(new[] { "--profile" }));
        line = "pseudohaptic replay --profile ";
        (_, _, string profiles) = Run($"[suggest:{line.Length}]", line);
        Assert.That(profiles.Split('\n', StringSplitOptions.RemoveEmptyEntries), Is.EquivalentTo(NamedProfiles.Names));
    }

    [Test]
    public void Progress_stays_off_a_redirected_standard_error()
    {
        // The child's standard error is a pipe, as in a script or a log: no progress, only the result on stdout.
        string outDir = Path.Combine(_dir, "demo");
        var r = ToolProcess.Run(_dir, "demo", "--out", outDir);
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(r.Stderr, Is.Empty, "no progress on a redirected standard error");
        Assert.That(r.Stdout, Does.Contain("demo: ").And.Contain("-> " + outDir));
    }

    [Test]
    public void An_unwritable_output_fails_before_any_work()
    {
        if (!ToolProcess.IsLinux) Assert.Ignore("/proc and /sys are Linux's");
        // /sys refuses new files even to root: the demo must say so at once, not after simulating every scene.
        var watch = System.Diagnostics.Stopwatch.StartNew();
        var (code, stderr, stdout) = Run("demo", "--out", "/sys/ph-demo-test");
        Assert.That(code, Is.EqualTo(1), stderr);
        Assert.That(stderr, Does.StartWith("pseudohaptic demo: --out /sys/ph-demo-test: cannot write: "));
        Assert.That(stdout, Is.Empty, "nothing computed, nothing printed");
        (code, stderr, _) = Run("accuracy", "--lifts", "all", "--mocap", "none", "--csv", "/sys/ph-accuracy.csv");
        Assert.That(code, Is.EqualTo(1), stderr);
        Assert.That(stderr, Does.StartWith("pseudohaptic accuracy: --csv /sys/ph-accuracy.csv: cannot write: "));
        Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(10), "refused before the work, which takes far longer");
        string scores = Write("S.csv", "participant,questionnaire,score\nP1,immersion,3\n");
        (code, stderr, _) = Run("report", "--scores", scores, "--out", "/sys/ph-report");
        Assert.That(code, Is.EqualTo(1), stderr);
        Assert.That(stderr, Does.StartWith("pseudohaptic report: --out /sys/ph-report: cannot write: "));
    }

    [Test]
    public void An_output_in_a_folder_that_allows_no_new_files_says_so_not_that_it_does_not_exist()
    {
        if (!ToolProcess.IsLinux) Assert.Ignore("/proc is Linux's");
        // /proc exists but creating a file in it fails with ENOENT (issue 32: it said "does not exist").
        string scores = Write("S.csv", "participant,questionnaire,score\nP1,immersion,3\n");
        string trace = Write("in.csv", "t,hand_y\n0,1\n0.1,1.05\n");
        foreach (var (command, args) in new[]
                 {
                     ("demo", new[] { "demo", "--out", "/proc/x" }),
                     ("report", new[] { "report", "--scores", scores, "--out", "/proc/x" }),
                     ("replay", new[] { "replay", "--trace", trace, "--out", "/proc/x", "--mass-kg", "1" }),
                 })
        {
            var (code, stderr, _) = Run(args);
            Assert.That(code, Is.EqualTo(1), stderr);
            Assert.That(stderr, Is.EqualTo($"pseudohaptic {command}: --out /proc/x: cannot write: cannot create files in /proc (the folder exists, but its file system does not allow new files)\n"));
        }
    }

    [Test]
    public void A_folder_output_on_a_full_device_says_cannot_write_naming_the_users_path_exit_1()
    {
        // Issue 12 item 5 and the README's table: "cannot write: REASON, exit 1, naming your path"; a folder output
        // printed only "No space left on device".
        if (!ToolProcess.IsLinux) Assert.Ignore("tmpfs mounts: Linux");
        string disk = Path.Combine(_dir, "small");
        Directory.CreateDirectory(disk);
        if (Process("mount", "-t", "tmpfs", "-o", "size=4k", "tmpfs", disk) != 0) Assert.Ignore("mounting a 4 KiB tmpfs needs root; a full device is not tested here");
        try
        {
            string examples = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "study");
            string scores = Write("S.csv", "participant,questionnaire,score\nP1,immersion,3\nP2,immersion,4\n");
            foreach (var args in new[]
                     {
                         new[] { "report", "--scores", scores, "--out", Path.Combine(disk, "r") },
                         new[] { "psychometric", "--trials", Path.Combine(examples, "trials.csv"), "--out", Path.Combine(disk, "r"), "--bootstrap", "0" },
                         new[] { "compare", "--scores", Path.Combine(examples, "psychophysics.csv"), "--out", Path.Combine(disk, "r") },
                         new[] { "demo", "--out", Path.Combine(disk, "r") },
                     })
            {
                var (code, stderr, _) = Run(args);
                Assert.That(code, Is.EqualTo(1), stderr);
                Assert.That(stderr, Does.StartWith($"pseudohaptic {args[0]}: --out {Path.Combine(disk, "r")}: cannot write: "));
                Assert.That(stderr.TrimEnd('\n'), Does.Not.Contain("\n").And.Not.Contain(".ph"), "one line, never the temporary folder");
                Assert.That(Directory.GetFileSystemEntries(disk), Is.Empty, args[0] + ": nothing left, no half folder");
            }
        }
        finally
        {
            Process("umount", "-l", disk);
        }
    }

    [Test]
    public void An_input_that_cannot_be_read_is_an_input_output_error_exit_1()
    {
        // Issue 25: "2 for usage and input errors, 1 for I/O"; the help and README say 1 when "a file could not be read".
        if (!ToolProcess.IsLinux) Assert.Ignore("/proc is Linux's");
        // /proc/self/mem opens, and reading its first page fails (EIO): a device error, not a malformed file.
        var (code, stderr, _) = Run("replay", "--trace", "/proc/self/mem", "--out", Path.Combine(_dir, "o.csv"), "--mass-kg", "1");
        Assert.That(code, Is.EqualTo(1), stderr);
        Assert.That(stderr, Does.StartWith("pseudohaptic replay: --trace /proc/self/mem: cannot read: "));
        (code, stderr, _) = Run("score", "--responses", "/proc/self/mem", "--out", Path.Combine(_dir, "s.csv"));
        Assert.That(code, Is.EqualTo(1), stderr);
        Assert.That(stderr, Does.StartWith("pseudohaptic score: --responses /proc/self/mem: cannot read: "));
        Assert.That(Directory.GetFileSystemEntries(_dir), Is.Empty, "nothing written");
        // A missing input stays an input error.
        (code, stderr, _) = Run("replay", "--trace", Path.Combine(_dir, "none.csv"), "--out", Path.Combine(_dir, "o.csv"), "--mass-kg", "1");
        Assert.That(code, Is.EqualTo(2), stderr);
        Assert.That(stderr, Does.EndWith("none.csv: does not exist\n"));
    }

    [Test]
    public void Unity_package_says_why_its_folder_cannot_be_created()
    {
        // Issue 32: "--out /proc/x says 'does not exist' where the reason is that the folder cannot be created"; every
        // other command was mended, unity-package still said it.
        if (!ToolProcess.IsLinux) Assert.Ignore("/proc is Linux's");
        string package = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic");
        var (code, stderr, _) = Run("unity-package", "--out", "/proc/x", "--package", package);
        Assert.That(code, Is.EqualTo(1), stderr);
        Assert.That(stderr, Is.EqualTo("pseudohaptic unity-package: --out /proc/x: cannot write: cannot create files in /proc (the folder exists, but its file system does not allow new files)\n"));
        string file = Write("afile", "");
        (code, stderr, _) = Run("unity-package", "--out", Path.Combine(file, "x", "y"), "--package", package);
        Assert.That(code, Is.EqualTo(2), stderr);
        Assert.That(stderr, Is.EqualTo($"pseudohaptic unity-package: --out {Path.Combine(file, "x", "y")}: {file} is not a folder\n"));
    }

    static int Process(string file, params string[] args)
    {
        var start = new System.Diagnostics.ProcessStartInfo(file) { RedirectStandardError = true, RedirectStandardOutput = true };
        foreach (string a in args) start.ArgumentList.Add(a);
        try
        {
            using var p = System.Diagnostics.Process.Start(start)!;
            p.StandardOutput.ReadToEnd();
            p.StandardError.ReadToEnd();
            p.WaitForExit();
            return p.ExitCode;
        }
        catch (System.ComponentModel.Win32Exception) { return -1; }
    }

    [Test]
    public void Options_given_with_an_equals_sign_and_values_that_look_like_options_are_taken()
    {
        string trace = Write("in.csv", "t,hand_y\n0,1\n0.1,1.05\n");
        string output = Path.Combine(_dir, "--svg");
        var (code, stderr, stdout) = Run("replay", "--trace", trace, $"--out={output}", "--mass-kg", "1", "--grab-offset", "-0.05");
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.Exists(output), "a file named --svg, given with '='");
        Assert.That(Regex.IsMatch(stdout, @"^replay: 2 rows, 1 hold, largest offset \d+\.\d mm -> .*--svg\n$"), stdout);
    }
}
