using Microsoft.CodeAnalysis;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.UnityCompile;

/// <summary>Every asmdef of the package compiles as Unity compiles it, for the editor on Android and for the Android player.</summary>
public class PerAsmdefCompileTests
{
    static readonly UnityProject Project = new(UnityProject.FindRoot());
    static readonly Lazy<BuildResult> Editor = new(() => UnityCompilation.Build(Project, UnityTarget.EditorAndroid));
    static readonly Lazy<BuildResult> Player = new(() => UnityCompilation.Build(Project, UnityTarget.PlayerAndroid));

    static string Report(BuildResult r) => string.Join("\n", r.Problems(DiagnosticSeverity.Warning).Take(40));

    [Test]
    public void EveryAsmdefCompilesForTheEditorOnAndroidWithoutAWarning()
    {
        Assert.That(Editor.Value.Problems(DiagnosticSeverity.Warning).Count(), Is.Zero, Report(Editor.Value));
        Assert.That(Editor.Value.Warnings, Is.Empty);
    }

    [Test]
    public void EveryAsmdefCompilesForTheAndroidPlayerWithoutAWarning()
    {
        Assert.That(Player.Value.Problems(DiagnosticSeverity.Warning).Count(), Is.Zero, Report(Player.Value));
        Assert.That(Player.Value.Warnings, Is.Empty);
    }

    [Test]
    public void TheEditorCompilesEveryAssemblyAndThePlayerNeitherTheEditorNorTheTests()
    {
        string[] runtime =
        {
            "Kosmos.PseudoHaptic", "Kosmos.PseudoHaptic.Core", "Kosmos.PseudoHaptic.Evaluation", "Kosmos.PseudoHaptic.Interaction",
            "Kosmos.PseudoHaptic.Logic", "Kosmos.PseudoHaptic.Meta", "Kosmos.PseudoHaptic.XRHands", "Assembly-CSharp",
        };
        Assert.That(Editor.Value.Compiled.Keys, Is.EquivalentTo(runtime.Concat(new[] { "Kosmos.PseudoHaptic.Editor", "Kosmos.PseudoHaptic.Tests.Editor", "Kosmos.PseudoHaptic.Tests.Runtime" })));
        Assert.That(Editor.Value.LeftOut, Is.Empty);
        Assert.That(Player.Value.Compiled.Keys, Is.EquivalentTo(runtime));
        Assert.That(Player.Value.LeftOut.Keys, Is.EquivalentTo(new[] { "Kosmos.PseudoHaptic.Editor", "Kosmos.PseudoHaptic.Tests.Editor", "Kosmos.PseudoHaptic.Tests.Runtime" }));
    }

    [Test]
    public void AMissingAsmdefReferenceFailsTheBuild()
    {
        // The components use the Logic assembly's HeldObject, HandGrab, …: without the reference they cannot compile.
        BuildResult r = UnityCompilation.Build(Project, UnityTarget.EditorAndroid,
            a => a.Name == "Kosmos.PseudoHaptic" ? a with { References = a.References.Where(x => x != "Kosmos.PseudoHaptic.Logic").ToList() } : a);
        var errors = r.Compiled["Kosmos.PseudoHaptic"].Where(d => d.Severity == DiagnosticSeverity.Error).ToList();
        Assert.That(errors.Select(e => e.Id), Does.Contain("CS0246"), "a type of the unreferenced assembly is not found");
    }

    [Test]
    public void AForeignAssemblyMissingFromTheReferencesFailsTheBuild()
    {
        BuildResult r = UnityCompilation.Build(Project, UnityTarget.EditorAndroid,
            a => a.Name == "Kosmos.PseudoHaptic.Meta" ? a with { References = a.References.Where(x => x != "Oculus.VR").ToList() } : a);
        Assert.That(r.Compiled["Kosmos.PseudoHaptic.Meta"].Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.Id), Does.Contain("CS0246"), "OVRHand is not found");
    }

    [Test]
    public void AnUnmetDefineConstraintLeavesTheAssemblyOutAndItsDependentsLoseIt()
    {
        BuildResult r = UnityCompilation.Build(Project, UnityTarget.EditorAndroid,
            a => a.Name == "Kosmos.PseudoHaptic.Meta" ? a with { VersionDefines = new List<(string, string, string)> { ("com.meta.xr.sdk.core", "[99.0.0,)", "KOSMOS_META_XR_CORE") } } : a);
        Assert.That(r.LeftOut, Does.ContainKey("Kosmos.PseudoHaptic.Meta"));
        Assert.That(r.Warnings, Has.Some.Contains("not a valid expression"), "[99.0.0,) is no form Unity accepts");
    }

    [Test]
    public void NUnitAndTheTestFrameworksConstraintsMakeIsAmbiguous()
    {
        // The shape of the CS0104 Unity reported in Tests/Editor/Logic/SessionLogTests.cs: both namespaces imported.
        const string source = "using NUnit.Framework;\nusing UnityEngine.TestTools.Constraints;\nnamespace K { public class T { [Test] public void A() { Assert.That(1, Is.EqualTo(1)); } } }\n";
        BuildResult r = UnityCompilation.Build(Project, UnityTarget.EditorAndroid, null, new Dictionary<string, string> { ["SessionLogTests.cs"] = source });
        Assert.That(r.Compiled["Kosmos.PseudoHaptic.Tests.Editor"].Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.Id), Does.Contain("CS0104"));
    }

    [Test]
    public void ARuntimeFileThatUsesTheEditorFailsThePlayerBuildOnly()
    {
        const string source = "\nnamespace Kosmos.PseudoHaptic { static class UsesEditor { static void A() => UnityEditor.AssetDatabase.SaveAssets(); } }\n";
        var files = new Dictionary<string, string> { ["Vectors.cs"] = File.ReadAllText(Path.Combine(Project.PackageFolder, "Runtime", "Unity", "Vectors.cs")) + source };
        BuildResult editor = UnityCompilation.Build(Project, UnityTarget.EditorAndroid, null, files);
        BuildResult player = UnityCompilation.Build(Project, UnityTarget.PlayerAndroid, null, files);
        Assert.That(editor.Compiled["Kosmos.PseudoHaptic"].Count(d => d.Severity == DiagnosticSeverity.Error), Is.Zero);
        Assert.That(player.Compiled["Kosmos.PseudoHaptic"].Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.Id), Has.Some.AnyOf("CS0103", "CS0234", "CS0246"), "UnityEditor is not referenced by a player build");
    }
}
