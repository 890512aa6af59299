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
    /// Issue 34: the XR Interaction Toolkit assembly compiles with XRI 2.x (2.5.4 pinned, above; 2.6.5) against the double's
    /// 2.5.4 declarations and with XRI 3.x against its 3.0.8 declarations (the double's XRI_3, selected by the manifest's
    /// version as the asmdef's KOSMOS_XRI_3 is), the editor's sample builder included; without XRI, or with an XRI 4 (not
    /// read), it is left out and everything else compiles, all without a warning.
    /// </summary>
    [TestCase(null, false, TestName = "Without XRI in the manifest the XRI assembly is left out and the rest compiles")]
    [TestCase("2.6.5", true, TestName = "With XRI 2.6.5 the XRI assembly compiles")]
    [TestCase("3.0.8", true, TestName = "With XRI 3.0.8 the XRI assembly compiles against XRI 3's declarations")]
    [TestCase("3.0.11", true, TestName = "With XRI 3.0.11 the XRI assembly compiles against XRI 3's declarations")]
    [TestCase("4.0.0", false, TestName = "With an XRI 4 the XRI assembly is left out and the rest compiles")]
    public void TheXriAssemblyCompilesWithXri2And3(string? version, bool compiles)
    {
        UnityProject project = Project.WithPackage("com.unity.xr.interaction.toolkit", version);
        foreach (UnityTarget target in new[] { UnityTarget.EditorAndroid, UnityTarget.PlayerAndroid })
        {
            BuildResult r = UnityCompilation.Build(project, target);
            Assert.That(r.Problems(DiagnosticSeverity.Warning), Is.Empty, target + ":\n" + Report(r));
            Assert.That(r.Warnings, Is.Empty);
            if (compiles)
            {
                Assert.That(r.Compiled.Keys, Does.Contain("Kosmos.PseudoHaptic.XRI"), target.ToString());
                if (target == UnityTarget.EditorAndroid) Assert.That(r.Compiled.Keys, Does.Contain("Kosmos.PseudoHaptic.Editor"));
            }
            else
            {
                Assert.That(r.LeftOut.Keys, Does.Contain("Kosmos.PseudoHaptic.XRI"), target.ToString());
                Assert.That(r.Compiled.Keys, Does.Contain("Kosmos.PseudoHaptic").And.Contain("Assembly-CSharp"), target.ToString());
            }
        }
    }

    /// <summary>The double's XRI 3 declarations are selected by the manifest's version: from 3.0.0, below 4.0.0, and only there.</summary>
    [TestCase("2.5.4", false)]
    [TestCase("2.6.5", false)]
    [TestCase("3.0.0", true)]
    [TestCase("3.0.8", true)]
    [TestCase("3.5.1", true)]
    [TestCase("4.0.0", false)]
    public void TheDoublesXri3DeclarationsFollowTheManifest(string version, bool xri3)
    {
        var defines = UnityCompilation.DoubleDefines(Project.WithPackage("com.unity.xr.interaction.toolkit", version).PackageVersions);
        Assert.That(defines["Unity.XR.Interaction.Toolkit"].Contains("XRI_3"), Is.EqualTo(xri3));
    }

    /// <summary>
    /// The two majors are different APIs: the transformer written for one does not compile against the other's declarations
    /// (so each case above compiles the code path of its own version, not a shape both happen to accept).
    /// </summary>
    [TestCase("2.5.4", "KOSMOS_XRI_3", TestName = "XRI 3's code path does not compile against XRI 2.5.4")]
    [TestCase("3.0.8", "", TestName = "XRI 2's code path does not compile against XRI 3.0.8")]
    public void EachMajorsCodePathNeedsItsOwnDeclarations(string version, string forced)
    {
        UnityProject project = Project.WithPackage("com.unity.xr.interaction.toolkit", version);
        BuildResult r = UnityCompilation.Build(project, UnityTarget.EditorAndroid, a => a.Name != "Kosmos.PseudoHaptic.XRI" ? a
            : a with { VersionDefines = forced.Length == 0
                ? new List<(string, string, string)> { ("com.unity.xr.interaction.toolkit", "[2.5.0,4.0.0)", "KOSMOS_XRI") }
                : new List<(string, string, string)> { ("com.unity.xr.interaction.toolkit", "[2.5.0,4.0.0)", "KOSMOS_XRI"), ("com.unity.xr.interaction.toolkit", "[2.5.0,4.0.0)", forced) } });
        Assert.That(r.Compiled["Kosmos.PseudoHaptic.XRI"].Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.Id), Has.Some.AnyOf("CS0246", "CS0234", "CS0103"));
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
