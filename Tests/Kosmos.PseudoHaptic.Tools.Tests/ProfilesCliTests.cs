using Kosmos.PseudoHaptic.Cli.Commands;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 33's tool: <c>pseudohaptic profiles</c> lists what the effects declare, <c>--show NAME --json</c> writes the file
/// every <c>--profile</c> takes, and a named profile and its file give the same replay byte for byte; a bad file is one
/// line naming the file, the line, the effect and the setting, exit 2.
/// </summary>
public class ProfilesCliTests : CliTestFolder
{
    public ProfilesCliTests() : base("ph-profiles-") { }

    static string Example(string name) => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", name);

    static (int code, string stderr, string stdout) Run(params string[] args) => Capture(() => Cli.Cli.Run(args));

    string ShowJson(string name)
    {
        string path = Path.Combine(_dir, name + ".json");
        var (code, err, _) = Run("profiles", "--show", name, "--json", "--out", path);
        Assert.That(code, Is.EqualTo(0), err);
        return path;
    }

    /// <summary>The listing, written to a file (the command writes standard output as a raw stream, which Capture does not see).</summary>
    (int code, string stderr, string listing) Listing()
    {
        string path = Path.Combine(_dir, "listing.txt");
        var (code, err, said) = Run("profiles", "--out", path);
        Assert.That(said, Does.StartWith($"profiles: {NamedProfiles.Names.Count} named profiles, {EffectRegistry.All.Count} effects -> "));
        return (code, err, code == 0 ? File.ReadAllText(path) : "");
    }

    [Test]
    public void TheListingShowsEveryNamedProfileAndEveryEffectWithItsSettingsUnitsAndDefaults()
    {
        var (code, err, listing) = Listing();
        Assert.That(code, Is.EqualTo(0), err);
        Assert.That(listing, Is.EqualTo(ProfilesCommand.Listing()));
        foreach (string name in NamedProfiles.Names) Assert.That(listing, Does.Contain("\n  " + name + " "));
        foreach (var d in EffectRegistry.All)
        {
            Assert.That(listing, Does.Contain("  " + d.Name + " [" + d.Stage + "]: " + d.Summary + "\n"));
            foreach (var s in d.Settings)
                Assert.That(listing, Does.Contain("      " + s.Name + " = " + s.Format(s.Default) + (s.Unit.Length > 0 ? " " + s.Unit : "") + " (" + s.RangeText + "): " + s.Summary + "\n"));
        }
        Assert.That(listing, Does.Contain("offset-correction [ObjectMotion]").And.Contain("threshold = 0.2 m ([0.001, 10])"));
    }

    [TestCaseSource(typeof(NamedProfiles), nameof(NamedProfiles.Names))]
    public void ANamedProfileAndItsFileGiveTheSameReplayByteForByte(string name)
    {
        string file = ShowJson(name);
        foreach (var (trace, mass) in new[] { ("lift.csv", "2"), ("walk-and-turn.csv", "0.5") })
        {
            string byName = Path.Combine(_dir, "by-name.csv"), byFile = Path.Combine(_dir, "by-file.csv");
            var a = Run("replay", "--trace", Example(trace), "--out", byName, "--mass-kg", mass, "--profile", name);
            var b = Run("replay", "--trace", Example(trace), "--out", byFile, "--mass-kg", mass, "--profile", file);
            Assert.That(a.code, Is.EqualTo(0), a.stderr);
            Assert.That(b.code, Is.EqualTo(0), b.stderr);
            Assert.That(File.ReadAllBytes(byFile), Is.EqualTo(File.ReadAllBytes(byName)), name + " on " + trace);
            Assert.That(b.stderr, Is.EqualTo(a.stderr), "the calibration line names the same profile");
        }
    }

    [Test]
    public void AChangedSettingInTheFileChangesTheReplay()
    {
        string file = ShowJson("gain");
        File.WriteAllText(file, File.ReadAllText(file).Replace("\"name\": \"gain\"", "\"name\": \"lighter-floor\"").Replace("\"floor\": 0", "\"floor\": 0.9"));
        string byName = Path.Combine(_dir, "gain.csv"), byFile = Path.Combine(_dir, "mine.csv");
        Assert.That(Run("replay", "--trace", Example("lift.csv"), "--out", byName, "--mass-kg", "2", "--profile", "gain").code, Is.EqualTo(0));
        var (code, err, _) = Run("replay", "--trace", Example("lift.csv"), "--out", byFile, "--mass-kg", "2", "--profile", file);
        Assert.That(code, Is.EqualTo(0), err);
        Assert.That(err, Does.Contain("under lighter-floor"));
        var rows = File.ReadAllLines(byFile).Skip(1).Select(l => double.Parse(l.Split(',')[2], System.Globalization.CultureInfo.InvariantCulture)).ToArray();
        Assert.That(rows.Min(), Is.GreaterThanOrEqualTo(0.9), "the file's floor holds the object up");
        Assert.That(File.ReadAllText(byFile), Is.Not.EqualTo(File.ReadAllText(byName)));
    }

    [TestCase("\"threshold\": 0.2", "\"threshold\": 20", "effect 'offset-correction': setting 'threshold': threshold must lie in [0.001, 10], got 20")]
    [TestCase("\"effect\": \"speed-cap\"", "\"effect\": \"speed-capp\"", "effect 'speed-capp' is unknown; known effects:")]
    [TestCase("\"headroom\": 2.5", "\"headroom\": \"fast\"", "effect 'speed-cap': setting 'headroom': must be a number")]
    [TestCase("\"slack\": 0.005", "\"slak\": 0.005", "effect 'lowering-guard': unknown setting 'slak'; its settings: slack")]
    public void ABadFileIsOneLineNamingTheFileLineEffectAndSetting(string from, string to, string message)
    {
        string file = ShowJson("paper");
        string text = File.ReadAllText(file);
        Assert.That(text, Does.Contain(from));
        File.WriteAllText(file, text.Replace(from, to));
        int line = text.Substring(0, text.IndexOf(from, StringComparison.Ordinal)).Count(c => c == '\n') + 1;
        string output = Path.Combine(_dir, "out.csv");
        var (code, err, _) = Run("replay", "--trace", Example("lift.csv"), "--out", output, "--mass-kg", "2", "--profile", file);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(err, Is.EqualTo($"pseudohaptic replay: option --profile: {file}:{line}: {message}\n").Or.StartWith($"pseudohaptic replay: option --profile: {file}:{line}: {message} "));
        Assert.That(err.TrimEnd('\n'), Does.Not.Contain("\n"));
        Assert.That(File.Exists(output), Is.False, "nothing written");
    }

    [Test]
    public void AnUnknownNameOrAMissingFileIsRefused()
    {
        var (code, err, _) = Run("profiles", "--show", "feather");
        Assert.That(code, Is.EqualTo(2));
        Assert.That(err, Does.StartWith("pseudohaptic profiles: option --show: unknown profile 'feather'; expected paper, paper-experiment, gain, xyz, paper-literal or a profile file FILE.json"));
        (code, err, _) = Run("replay", "--trace", Example("lift.csv"), "--out", Path.Combine(_dir, "o.csv"), "--mass-kg", "2", "--profile", Path.Combine(_dir, "none.json"));
        Assert.That(code, Is.Not.EqualTo(0));
        Assert.That(err, Does.Contain("--profile").And.Contain("none.json"));
        (code, err, _) = Run("profiles", "--json");
        Assert.That(code, Is.EqualTo(2));
        Assert.That(err, Does.Contain("--json: needs --show NAME"));
    }

    [Test]
    public void TheShownFileIsEveryEffectWithEverySetting()
    {
        string json = File.ReadAllText(ShowJson("xyz"));
        foreach (var e in NamedProfiles.Xyz.Effects)
        {
            Assert.That(json, Does.Contain("\"effect\": \"" + e.Name + "\""));
            foreach (var s in EffectRegistry.Of(e).Settings) Assert.That(json, Does.Contain("\"" + s.Name + "\": " + s.Format(s.Read(e))));
        }
        Assert.That(json, Is.EqualTo(ProfileJson.Write(NamedProfiles.Xyz)));
        string shown = Path.Combine(_dir, "shown.txt");
        var (code, err, _) = Run("profiles", "--show", ShowJson("paper"), "--out", shown);
        Assert.That(code, Is.EqualTo(0), err);
        string text = File.ReadAllText(shown);
        Assert.That(text, Is.EqualTo(ProfilesCommand.Show(NamedProfiles.Paper)), "a file shows as the profile it describes");
    }

    /// <summary>An effect the tool has never heard of (declared here, registered through the public API) is listed, written
    /// and replayed: the tool has no code per effect.</summary>
    [Test]
    public void AnEffectRegisteredOutsideThePackageIsListedWrittenAndReplayed()
    {
        EffectRegistry.Register(Nudge.Descriptor);
        var (code, _, listing) = Listing();
        Assert.That(code, Is.EqualTo(0));
        Assert.That(listing, Does.Contain("  nudge [Position]: raises the object by a fixed height\n      height = 0.01 m ([0, 0.5]): how far"));
        string file = Path.Combine(_dir, "nudged.json");
        File.WriteAllText(file, ProfileJson.Write(NamedProfiles.Gain.With(new Nudge(0.25), "nudged")));
        string plain = Path.Combine(_dir, "plain.csv"), nudged = Path.Combine(_dir, "nudged.csv");
        Assert.That(Run("replay", "--trace", Example("lift.csv"), "--out", plain, "--mass-kg", "2", "--profile", "gain").code, Is.EqualTo(0));
        var r = Run("replay", "--trace", Example("lift.csv"), "--out", nudged, "--mass-kg", "2", "--profile", file);
        Assert.That(r.code, Is.EqualTo(0), r.stderr);
        Assert.That(File.ReadAllText(nudged), Is.Not.EqualTo(File.ReadAllText(plain)));
    }

    public sealed class Nudge : WeightEffect
    {
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("nudge", EffectStage.Position, typeof(Nudge), "a tools test",
            "raises the object by a fixed height", s => new Nudge(s[0]),
            SettingDescriptor.Number<Nudge>("height", "m", 0.01, 0, 0.5, "how far", e => e.Height));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
        public double Height { get; }
        public Nudge(double height) { Height = Descriptor.Settings[0].Check(height); }
        protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => frame.NewObjectY += Height;
    }
}
