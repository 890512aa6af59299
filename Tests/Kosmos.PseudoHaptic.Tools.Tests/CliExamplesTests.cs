using System.Diagnostics;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Cli.Accuracy;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Every example is written as a user types it, and runs (issue 25): each ```sh block of README.md and of the
/// package's Documentation~ that holds a <c>pseudohaptic</c> line is run as a bash script, and so is every example
/// of every command's --help. They run in a scratch copy of the repository's example files (so nothing in the
/// clone is written), with <c>pseudohaptic</c> on the PATH as the built tool, from the repository's root or from
/// the folder a block names in a preceding <c>&lt;!-- examples run in: PATH --&gt;</c>. The one long command, the
/// accuracy page's, is run by <see cref="AccuracyPageTests"/>.
/// </summary>
public class CliExamplesTests
{
    string _sandbox = "";

    [OneTimeSetUp]
    public void CreateSandbox()
    {
        if (!OperatingSystem.IsLinux() && !OperatingSystem.IsMacOS()) Assert.Ignore("the examples are sh");
        _sandbox = Path.Combine(Path.GetTempPath(), "ph-examples-" + Guid.NewGuid().ToString("N"));
        // The whole package (3 MB): its examples, and its files for unity-package's example.
        string package = Path.Combine("Packages", "com.kosmos.pseudohaptic");
        Copy(Path.Combine(RepositoryRoot.Path, package), Path.Combine(_sandbox, package));
        Directory.CreateDirectory(Path.Combine(_sandbox, "bin"));
        string shim = Path.Combine(_sandbox, "bin", "pseudohaptic");
        File.WriteAllText(shim, $"#!/bin/sh\nexec dotnet '{Path.Combine(AppContext.BaseDirectory, "pseudohaptic.dll")}' \"$@\"\n");
        if (!OperatingSystem.IsWindows()) File.SetUnixFileMode(shim, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
    }

    [OneTimeTearDown]
    public void DeleteSandbox()
    {
        if (_sandbox.Length > 0 && Directory.Exists(_sandbox)) Directory.Delete(_sandbox, recursive: true);
    }

    static void Copy(string from, string to)
    {
        Directory.CreateDirectory(to);
        foreach (var file in Directory.GetFiles(from)) File.Copy(file, Path.Combine(to, Path.GetFileName(file)));
        foreach (var dir in Directory.GetDirectories(from)) Copy(dir, Path.Combine(to, Path.GetFileName(dir)));
    }

    public sealed record Block(string Document, int Line, string Folder, string Script)
    {
        public override string ToString() => $"{Document}:{Line}";
    }

    /// <summary>The sh blocks with a pseudohaptic line, in README.md and Documentation~/*.md.</summary>
    public static IEnumerable<Block> DocumentedBlocks()
    {
        string docs = Path.Combine("Packages", "com.kosmos.pseudohaptic", "Documentation~");
        var files = new[] { "README.md" }.Concat(Directory.GetFiles(Path.Combine(RepositoryRoot.Path, docs), "*.md").Select(f => Path.Combine(docs, Path.GetFileName(f))).OrderBy(f => f, StringComparer.Ordinal));
        foreach (var file in files)
        {
            var lines = File.ReadAllLines(Path.Combine(RepositoryRoot.Path, file));
            for (int i = 0; i < lines.Length; i++)
            {
                if (lines[i] != "```sh") continue;
                int end = Array.IndexOf(lines, "```", i + 1);
                var body = lines[(i + 1)..end];
                if (body.Any(l => l.StartsWith("pseudohaptic ", StringComparison.Ordinal)))
                {
                    var marker = i > 0 ? Regex.Match(lines[i - 1], @"^<!-- examples run in: (.+) -->$") : Match.Empty;
                    yield return new Block(file, i + 1, marker.Success ? marker.Groups[1].Value : ".", string.Join('\n', body) + "\n");
                }
                i = end;
            }
        }
    }

    public static IEnumerable<string> HelpExamples() => Cli.Cli.Define().SelectMany(c => c.Examples);

    (int Code, string Output) Bash(string folder, string script)
    {
        var info = new ProcessStartInfo("bash") { WorkingDirectory = Path.Combine(_sandbox, folder), RedirectStandardOutput = true, RedirectStandardError = true, RedirectStandardInput = true, UseShellExecute = false };
        info.ArgumentList.Add("-e");
        info.ArgumentList.Add("-c");
        info.ArgumentList.Add(script);
        info.Environment["PATH"] = Path.Combine(_sandbox, "bin") + ":" + Environment.GetEnvironmentVariable("PATH");
        info.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        using var p = Process.Start(info)!;
        p.StandardInput.Close();
        var stdout = p.StandardOutput.ReadToEndAsync();
        var stderr = p.StandardError.ReadToEndAsync();
        if (!p.WaitForExit(TimeSpan.FromMinutes(5)))
        {
            p.Kill(entireProcessTree: true);
            Assert.Fail("did not end within 5 minutes: " + script);
        }
        p.WaitForExit();
        return (p.ExitCode, stdout.Result + stderr.Result);
    }

    [TestCaseSource(nameof(DocumentedBlocks))]
    public void Every_documented_example_runs(Block block)
    {
        string script = block.Script;
        // The accuracy page's command takes two minutes and is AccuracyPageTests' to run.
        if (script.Contains(AccuracyMarkdown.Command, StringComparison.Ordinal)) script = script.Replace(AccuracyMarkdown.Command, "");
        Directory.CreateDirectory(Path.Combine(_sandbox, block.Folder));
        var before = Snapshot(_sandbox);
        var (code, output) = Bash(block.Folder, script);
        Assert.That(code, Is.EqualTo(0), $"{block}:\n{script}\n{output}");
        AssertWroteOnlyUnderOut(before, block.ToString());
    }

    [TestCaseSource(nameof(HelpExamples))]
    public void Every_help_example_runs(string example)
    {
        // As the help says: from the repository's root, after mkdir -p out.
        Directory.CreateDirectory(Path.Combine(_sandbox, "out"));
        var before = Snapshot(_sandbox);
        var (code, output) = Bash(".", example);
        Assert.That(code, Is.EqualTo(0), example + "\n" + output);
        AssertWroteOnlyUnderOut(before, example);
    }

    /// <summary>Every file and folder below <paramref name="root"/> with its size and time of last change.</summary>
    static Dictionary<string, (long Size, DateTime Changed)> Snapshot(string root)
    {
        var files = new Dictionary<string, (long, DateTime)>(StringComparer.Ordinal);
        foreach (var entry in new DirectoryInfo(root).EnumerateFileSystemInfos("*", SearchOption.AllDirectories))
            files[Path.GetRelativePath(root, entry.FullName)] = (entry is FileInfo f ? f.Length : -1, entry is FileInfo ? entry.LastWriteTimeUtc : DateTime.MinValue);
        return files;
    }

    /// <summary>
    /// Issue 32: an example writes only under the repository's ignored <c>out/</c> (not <c>demo-lift/</c> at the
    /// root, not <c>out/</c> inside Documentation~): every file created, changed or removed elsewhere fails.
    /// </summary>
    void AssertWroteOnlyUnderOut(Dictionary<string, (long Size, DateTime Changed)> before, string example)
    {
        var after = Snapshot(_sandbox);
        var stray = after.Where(e => !UnderOut(e.Key) && (!before.TryGetValue(e.Key, out var was) || was != e.Value)).Select(e => e.Key)
            .Concat(before.Keys.Where(k => !UnderOut(k) && !after.ContainsKey(k)))
            .OrderBy(k => k, StringComparer.Ordinal).ToList();
        Assert.That(stray, Is.Empty, $"{example} writes outside out/: {string.Join(", ", stray)}");
    }

    static bool UnderOut(string path) => path == "out" || path.StartsWith("out" + Path.DirectorySeparatorChar, StringComparison.Ordinal);

    /// <summary>The check above can fail: a file written beside out/ is named.</summary>
    [Test]
    public void The_out_check_sees_a_file_written_outside_out()
    {
        var before = Snapshot(_sandbox);
        var (code, _) = Bash(".", "mkdir -p out && echo x > out/fine.txt && mkdir -p demo-lift && echo x > demo-lift/stray.csv");
        Assert.That(code, Is.Zero);
        try
        {
            var e = Assert.Throws<AssertionException>(() => AssertWroteOnlyUnderOut(before, "stray"));
            Assert.That(e!.Message, Does.Contain("demo-lift").And.Not.Contain("fine.txt"));
        }
        finally
        {
            Directory.Delete(Path.Combine(_sandbox, "demo-lift"), true);
        }
    }

    /// <summary>
    /// examples/study/run.sh regenerates the worked example: its working files go under out/, and besides them it
    /// writes only the copies it keeps in its own folder.
    /// </summary>
    [Test]
    public void The_study_example_script_writes_only_under_out_and_its_copies()
    {
        string study = Path.Combine("Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "study");
        var before = Snapshot(_sandbox);
        var (code, output) = Bash(study, "sh run.sh");
        Assert.That(code, Is.EqualTo(0), output);
        var copies = File.ReadAllLines(Path.Combine(_sandbox, study, "run.sh"))
            .Select(l => Regex.Match(l, "^cp \".+\" \"\\$HERE/([^\"]+)\"$")).Where(m => m.Success).Select(m => m.Groups[1].Value).ToList();
        Assert.That(copies, Has.Count.GreaterThanOrEqualTo(5), "the copies run.sh keeps");
        foreach (var copy in copies) before.Remove(Path.Combine(study, copy));
        var after = Snapshot(_sandbox);
        foreach (var copy in copies) after.Remove(Path.Combine(study, copy));
        Assert.That(Directory.Exists(Path.Combine(_sandbox, "out", "study-example", "fits")), "its working files under out/");
        var stray = after.Where(e => !UnderOut(e.Key) && (!before.TryGetValue(e.Key, out var was) || was != e.Value)).Select(e => e.Key).ToList();
        Assert.That(stray, Is.Empty, "run.sh writes outside out/: " + string.Join(", ", stray));
    }

    [Test]
    public void The_documents_examples_are_found_and_written_as_typed()
    {
        var blocks = DocumentedBlocks().ToList();
        Assert.That(blocks.Count, Is.GreaterThanOrEqualTo(8), string.Join(", ", blocks));
        Assert.That(blocks.Any(b => b.Script.Contains(AccuracyMarkdown.Command, StringComparison.Ordinal)), "the accuracy page's command is documented as run");
        // No example asks for 'dotnet run … --' to reach the tool: it is installed (README, "Install the command"). The one
        // exception is the README's first line, the demo a newcomer runs on a fresh machine before installing anything.
        const string FirstLine = "dotnet run --project Tools/Kosmos.PseudoHaptic.Cli -- demo ";
        string readme = File.ReadAllText(Path.Combine(RepositoryRoot.Path, "README.md"));
        string firstBlock = readme.Substring(readme.IndexOf("```", StringComparison.Ordinal)).Split('\n')[1];
        Assert.That(firstBlock, Does.StartWith(FirstLine), "the README's first command runs the demo");
        Assert.That(readme.Replace(FirstLine, ""), Does.Not.Contain("--project Tools/Kosmos.PseudoHaptic.Cli -- "), "README.md");
        foreach (var file in Directory.GetFiles(Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~"), "*.md"))
            Assert.That(File.ReadAllText(file), Does.Not.Contain("--project Tools/Kosmos.PseudoHaptic.Cli -- "), file);
    }
}
