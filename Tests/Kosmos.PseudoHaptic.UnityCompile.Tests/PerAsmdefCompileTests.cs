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
            "Kosmos.PseudoHaptic.Logic", "Kosmos.PseudoHaptic.Meta", "Kosmos.PseudoHaptic.XRHands", "Kosmos.PseudoHaptic.XRI", "Assembly-CSharp",
        };
        Assert.That(Editor.Value.Compiled.Keys, Is.EquivalentTo(runtime.Concat(new[] { "Kosmos.PseudoHaptic.Editor", "Kosmos.PseudoHaptic.Tests.Editor", "Kosmos.PseudoHaptic.Tests.Runtime" })));
        Assert.That(Editor.Value.LeftOut, Is.Empty);
        Assert.That(Player.Value.Compiled.Keys, Is.EquivalentTo(runtime));
        Assert.That(Player.Value.LeftOut.Keys, Is.EquivalentTo(new[] { "Kosmos.PseudoHaptic.Editor", "Kosmos.PseudoHaptic.Tests.Editor", "Kosmos.PseudoHaptic.Tests.Runtime" }));
    }

    /// <summary>
    /// Issue 34: the XR Interaction Toolkit assembly compiles when XRI 2.5.4 is in the manifest (above), and without XRI, or
    /// with XRI 3.x (whose types moved namespaces), it is left out while everything else, the editor's sample builder
    /// included, compiles without a warning.
    /// </summary>
    [TestCase(null, TestName = "Without XRI in the manifest the XRI assembly is left out and the rest compiles")]
    [TestCase("3.0.8", TestName = "With XRI 3.0.8 the XRI assembly is left out and the rest compiles")]
    [TestCase("2.6.5", TestName = "With XRI 2.6.5 the XRI assembly compiles")]
    public void TheXriAssemblyCompilesOnlyWithXri2(string? version)
    {
        UnityProject project = Project.WithPackage("com.unity.xr.interaction.toolkit", version);
        foreach (UnityTarget target in new[] { UnityTarget.EditorAndroid, UnityTarget.PlayerAndroid })
        {
            BuildResult r = UnityCompilation.Build(project, target);
            Assert.That(r.Problems(DiagnosticSeverity.Warning), Is.Empty, target + ":\n" + Report(r));
            Assert.That(r.Warnings, Is.Empty);
            if (version != null && version.StartsWith("2."))
                Assert.That(r.Compiled.Keys, Does.Contain("Kosmos.PseudoHaptic.XRI"), target.ToString());
            else
            {
                Assert.That(r.LeftOut.Keys, Does.Contain("Kosmos.PseudoHaptic.XRI"), target.ToString());
                Assert.That(r.Compiled.Keys, Does.Contain("Kosmos.PseudoHaptic").And.Contain("Assembly-CSharp"), target.ToString());
            }
        }
    }

    [Test]
    public void TheXriAssemblyNeedsItsXriReference()
    {
        BuildResult r = UnityCompilation.Build(Project, UnityTarget.EditorAndroid,
            a => a.Name == "Kosmos.PseudoHaptic.XRI" ? a with { References = a.References.Where(x => x != "Unity.XR.Interaction.Toolkit").ToList() } : a);
        Assert.That(r.Compiled["Kosmos.PseudoHaptic.XRI"].Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.Id), Does.Contain("CS0246"), "XRGrabInteractable is not found");
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
