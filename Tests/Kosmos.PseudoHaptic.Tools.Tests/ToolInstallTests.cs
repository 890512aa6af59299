using System.Diagnostics;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// The README's one install command (issue 25), run as written from the repository's root, with the .NET tools
/// home in a scratch folder (DOTNET_CLI_HOME) so the machine's own tools are untouched; then the installed
/// <c>pseudohaptic</c> from another folder: --version, --help, and a replay of an example. About a minute (a
/// Release build and pack). It writes the package to the clone's out/tool, which git ignores.
/// </summary>
public class ToolInstallTests
{
    [Test]
    [Category("Install")]
    public void The_readme_command_installs_pseudohaptic_which_then_runs_from_any_folder()
    {
        if (!OperatingSystem.IsLinux() && !OperatingSystem.IsMacOS()) Assert.Ignore("the install line is sh");
        string readme = File.ReadAllText(Path.Combine(RepositoryRoot.Path, "README.md"));
        var install = readme.Split('\n').Where(l => l.StartsWith("dotnet pack Tools/Kosmos.PseudoHaptic.Cli ", StringComparison.Ordinal)).Distinct().ToList();
        Assert.That(install, Has.Count.EqualTo(1), "one install command, the same wherever the README shows it");
        string home = Path.Combine(Path.GetTempPath(), "ph-install-" + Guid.NewGuid().ToString("N"));
        string elsewhere = Path.Combine(home, "elsewhere");
        Directory.CreateDirectory(elsewhere);
        try
        {
            var (code, output) = Run(RepositoryRoot.Path, home, "bash", "-e", "-c", install[0]);
            Assert.That(code, Is.EqualTo(0), install[0] + "\n" + output);
            string tool = Path.Combine(home, ".dotnet", "tools", "pseudohaptic");
            Assert.That(File.Exists(tool), tool);

            (code, output) = Run(elsewhere, home, tool, "--version");
            Assert.That(code, Is.EqualTo(0), output);
            // The package's major and minor (package.json), the number of commits, the commit.
            string[] package = System.Text.Json.JsonDocument.Parse(File.ReadAllText(Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "package.json")))
                .RootElement.GetProperty("version").GetString()!.Split('.');
            Assert.That(output.Trim(), Does.Match($@"^{package[0]}\.{package[1]}\.\d+\+[0-9a-f]{{7,}}"), "the version and the commit");
            (code, output) = Run(elsewhere, home, tool, "replay", "--help");
            Assert.That(code, Is.EqualTo(0), output);
            Assert.That(output, Does.Contain("--mass-kg"));
            string lift = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "lift.csv");
            (code, output) = Run(elsewhere, home, tool, "replay", "--trace", lift, "--out", "replayed.csv", "--mass-kg", "2");
            Assert.That(code, Is.EqualTo(0), output);
            Assert.That(File.Exists(Path.Combine(elsewhere, "replayed.csv")), "written in the folder it was run from");
        }
        finally { Directory.Delete(home, recursive: true); }
    }

    static (int Code, string Output) Run(string folder, string home, string file, params string[] args)
    {
        var info = new ProcessStartInfo(file) { WorkingDirectory = folder, RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var a in args) info.ArgumentList.Add(a);
        info.Environment["DOTNET_CLI_HOME"] = home;
        info.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        info.Environment["DOTNET_NOLOGO"] = "1";
        using var p = Process.Start(info)!;
        var stdout = p.StandardOutput.ReadToEndAsync();
        var stderr = p.StandardError.ReadToEndAsync();
        if (!p.WaitForExit(TimeSpan.FromMinutes(10)))
        {
            p.Kill(entireProcessTree: true);
            Assert.Fail($"{file} {string.Join(' ', args)} did not end within 10 minutes");
        }
        p.WaitForExit();
        return (p.ExitCode, stdout.Result + stderr.Result);
    }
}
