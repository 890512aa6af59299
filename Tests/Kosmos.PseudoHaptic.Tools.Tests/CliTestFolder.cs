using Kosmos.PseudoHaptic.Cli;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// What the in-process command tests share: a fresh temporary folder for each test (deleted after it), files
/// written into it, and a command run with its standard error and output captured.
/// </summary>
public abstract class CliTestFolder
{
    readonly string _prefix;
    protected string _dir = "";

    /// <param name="prefix">The start of the folder's name under the temporary path ("ph-study-").</param>
    protected CliTestFolder(string prefix) => _prefix = prefix;

    [SetUp]
    public void CreateFolder()
    {
        _dir = Path.Combine(Path.GetTempPath(), _prefix + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void DeleteFolder() => Directory.Delete(_dir, recursive: true);

    protected string Write(string name, string text)
    {
        string path = Path.Combine(_dir, name);
        File.WriteAllText(path, text);
        return path;
    }

    protected static (int code, string stderr, string stdout) Capture(Func<int> run)
    {
        var err = new StringWriter();
        var outWriter = new StringWriter();
        var oldErr = Console.Error;
        var oldOut = Console.Out;
        Console.SetError(err);
        Console.SetOut(outWriter);
        try { return (run(), err.ToString(), outWriter.ToString()); }
        finally
        {
            Console.SetError(oldErr);
            Console.SetOut(oldOut);
        }
    }

    protected static (int code, string stderr, string stdout) Score(params string[] args) => Capture(() => ScoreCommand.Run(args));
}
