using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// The package's own writer (<see cref="AtomicFile"/>, used in the headset by the questionnaire panel, the
/// calibration store and the session recorder), issue 12: replace semantics, short temporary names, racing
/// writers, no litter on failure.
/// </summary>
public class PackageAtomicFileTests
{
    string _dir = "";

    [SetUp]
    public void SetUp()
    {
        _dir = Path.Combine(Path.GetTempPath(), "ph-atomic-" + Guid.NewGuid().ToString("N")[..8]);
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void TearDown() => Directory.Delete(_dir, recursive: true);

    string[] Names() => Directory.GetFileSystemEntries(_dir).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).ToArray()!;

    [Test]
    public void ReplacesAnExistingFile()
    {
        string path = Path.Combine(_dir, "a.csv");
        AtomicFile.WriteAllText(path, "one");
        AtomicFile.WriteAllText(path, "two");
        Assert.That(File.ReadAllText(path), Is.EqualTo("two"));
        Assert.That(Names(), Is.EqualTo(new[] { "a.csv" }));
    }

    [Test]
    public void TheTemporaryNameIsShortSoA255CharacterNameWorks()
    {
        string name = new string('x', 251) + ".csv";
        string path = Path.Combine(_dir, name);
        string? seen = null;
        AtomicFile.WriteWith(path, temp => { seen = temp; File.WriteAllText(temp, "long"); });
        Assert.That(Path.GetFileName(seen!), Has.Length.EqualTo(15).And.StartWith(".ph").And.EndWith(".tmp"));
        Assert.That(File.ReadAllText(path), Is.EqualTo("long"));
        AtomicFile.WriteAllText(path, "again");
        Assert.That(Names(), Is.EqualTo(new[] { name }));
    }

    [Test]
    public void AFailingWriterLeavesTheOldFileAndNoLitter()
    {
        string path = Path.Combine(_dir, "a.csv");
        AtomicFile.WriteAllText(path, "old");
        Assert.Throws<InvalidOperationException>(() => AtomicFile.WriteWith(path, temp =>
        {
            File.WriteAllText(temp, "half");
            throw new InvalidOperationException("disk pulled");
        }));
        Assert.That(File.ReadAllText(path), Is.EqualTo("old"));
        Assert.That(Names(), Is.EqualTo(new[] { "a.csv" }));
    }

    [Test]
    public void AFolderAsTheDestinationFailsWithoutLitter()
    {
        Directory.CreateDirectory(Path.Combine(_dir, "f"));
        var e = Assert.Throws<IOException>(() => AtomicFile.WriteAllText(Path.Combine(_dir, "f"), "x"))!;
        Assert.That(e.Message, Does.Contain("is a folder"));
        Assert.That(Names(), Is.EqualTo(new[] { "f" }));
    }

    [Test]
    public void RacingWritersOfOneNewFileAllSucceed()
    {
        for (int round = 0; round < 20; round++)
        {
            string path = Path.Combine(_dir, $"r{round}.csv");
            var errors = new System.Collections.Concurrent.ConcurrentBag<Exception>();
            var threads = Enumerable.Range(0, 6).Select(k => new Thread(() =>
            {
                try { AtomicFile.WriteAllText(path, "writer " + k); }
                catch (Exception e) { errors.Add(e); }
            })).ToList();
            threads.ForEach(t => t.Start());
            threads.ForEach(t => t.Join());
            Assert.That(errors, Is.Empty, "round " + round);
            Assert.That(File.ReadAllText(path), Does.StartWith("writer "));
        }
        Assert.That(Names().Where(n => n.StartsWith(".ph", StringComparison.Ordinal)), Is.Empty);
    }

    [Test]
    public void OnLinuxTheFolderIsSyncedThroughLibc()
    {
        if (!OperatingSystem.IsLinux()) Assert.Ignore("the folder is synced through libc on Linux, Android and macOS only");
        AtomicFile.WriteAllText(Path.Combine(_dir, "a.csv"), "x");
        Assert.That(AtomicFile.DirectorySync, Is.EqualTo(AtomicFile.DirectorySyncKind.Synced));
        var e = Assert.Throws<IOException>(() => AtomicFile.SyncDirectory(Path.Combine(_dir, "missing")))!;
        Assert.That(e.Message, Does.Contain("errno 2"), "ENOENT is reported, not swallowed");
    }

    [Test]
    public void CreateDirectoryMakesEveryMissingParent()
    {
        string deep = Path.Combine(_dir, "p", "q", "r");
        AtomicFile.CreateDirectory(deep);
        Assert.That(Directory.Exists(deep), Is.True);
        AtomicFile.CreateDirectory(deep); // there already: nothing to do
    }
}
