using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Unity's built-in modules (<c>com.unity.modules.*</c>) are packages: one that is not enabled is a compile error
/// in every assembly that names its types. The project's <c>Packages/manifest.json</c> enables every module that
/// the pinned packages' sources use, and the package's own <c>package.json</c> declares the modules its own code
/// uses. Both lists are held here.
/// </summary>
public class BuiltInModuleTests
{
    static readonly string Package = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic");

    /// <summary>
    /// The versions the project pins; the declarations in Tests/UnityDouble are transcribed from these.
    /// </summary>
    static readonly (string Name, string Version)[] Pinned =
    {
        ("com.meta.xr.sdk.core", "68.0.2"),
        ("com.meta.xr.sdk.interaction.ovr", "68.0.0"), // pulls com.meta.xr.sdk.interaction 68.0.0
        ("com.unity.test-framework", "1.1.33"),
        ("com.unity.xr.management", "4.4.0"),
        ("com.unity.xr.oculus", "4.2.0"),
        ("com.unity.xr.hands", "1.5.0"), // the second hand source (Runtime/XRHands); needs OpenXR to report hands
        ("com.unity.xr.interaction.toolkit", "2.5.4"), // the XRI grab transformer (Runtime/XRI), the version Unity 2022.3 releases
    };

    /// <summary>
    /// Every module the pinned packages use, with one use found in their sources (read at the pinned tags of
    /// icosa-mirror/com.meta.xr.sdk.core 68.0.2, darktable-mirror/com.meta.xr.sdk.interaction v68.0.0,
    /// needle-mirror/com.unity.xr.management 4.4.0 and needle-mirror/com.unity.xr.oculus 4.2.0; assemblies whose
    /// defineConstraints this project never meets — the NGO and Photon Fusion multiplayer blocks, ISDK's
    /// USE_OPENXR UnityXR assemblies — and Samples~ are left out). The sources of com.meta.xr.sdk.interaction.ovr
    /// 68.0.0 were not available to read; its package.json depends only on the two Meta packages above.
    /// </summary>
    static readonly (string Module, string Evidence)[] UsedByPinnedPackages =
    {
        ("ai", "UnityEngine.AI.NavMesh: ISDK Runtime/Scripts/Interaction/Surfaces/NavMeshSurface.cs"),
        ("androidjni", "AndroidJavaClass: Core Scripts/OVRManager.cs; AndroidJavaProxy: Scripts/OVROnCompleteListener.cs"),
        ("animation", "Animator: Core Scripts/Util/OVRControllerHelper.cs, ISDK Runtime/Scripts/Input/Hands/ControllerAnimatedHand.cs"),
        ("assetbundle", "AssetBundle: Core Scripts/OVRResources.cs, Scripts/OVRSceneLoader.cs"),
        ("audio", "AudioClip: Core Scripts/OVRHapticsClip.cs; AudioSettings: com.unity.xr.oculus Editor/OculusBuildProcessor.cs"),
        ("imageconversion", "ImageConversion.LoadImage: Core Scripts/OVRGLTFLoader.cs; EncodeToPNG: Scripts/Util/OVRCubemapCapture.cs"),
        ("imgui", "GUILayout/GUIContent: every editor of Core, ISDK and XR Management; this package's Editor"),
        ("jsonserialize", "JsonUtility: Core Scripts/InputActions/RuntimeSettings.cs; this package's UserCalibrationStore"),
        ("particlesystem", "ParticleSystemRenderer: ISDK Runtime/Sample/Scripts/PoseUseSample.cs (assembly Oculus.Interaction.Samples, always compiled)"),
        ("physics", "Collider, Rigidbody: Core Scripts/OVRInput.cs, ISDK throughout; this package"),
        ("physics2d", "Physics2D.GetRayIntersectionAll: Core Scripts/Util/OVRRaycaster.cs"),
        ("subsystems", "SubsystemManager: Core Scripts/OVRManager.cs; ISubsystem: XR Management Runtime/XRLoader.cs; SubsystemWithProvider: XR Hands Runtime/XRHandSubsystem.cs"),
        ("ui", "Canvas: Core Scripts/OVROverlayCanvas.cs, ISDK Runtime/Scripts/Unity/PointableCanvas.cs (and com.unity.ugui)"),
        ("uielements", "UnityEngine.UIElements: Core Editor/Utils/StatusMenu/StatusIcon.cs, XR Management Runtime/XRManagerSettings.cs"),
        ("unitywebrequest", "UnityWebRequest: Core Editor/OVRPlatformTool.cs, Editor/BuildingBlocks/BlocksContentManager.cs"),
        ("vr", "XRSettings, XRDevice: Core Scripts/OVRCommon.cs, Scripts/OVROverlayCanvas.cs; XRStats: com.unity.xr.oculus Runtime/OculusPerformance.cs"),
        ("xr", "InputTracking, XRNode: Core Scripts/OVRCommon.cs; XRDisplaySubsystem: com.unity.xr.oculus Runtime/OculusLoader.cs; InputTrackingState: com.unity.xr.interaction.toolkit 2.5.4 Runtime/Interaction/Controllers/XRBaseController.cs"),
    };

    /// <summary>
    /// What this package's own Unity-facing code would need each module for: a type of that module, matched as a
    /// whole word in the package's C# (comments and strings removed). TextMesh, Font, Gizmos and the rest of the
    /// engine core are in no optional module.
    /// </summary>
    static readonly (string Module, string Types)[] ModuleTypes =
    {
        ("ai", @"NavMesh\w*"),
        ("androidjni", @"AndroidJava\w+|AndroidJNI\w*"),
        ("animation", @"Animator\w*|AnimationClip|Animation|Avatar|HumanBodyBones"),
        ("assetbundle", @"AssetBundle\w*"),
        ("audio", @"Audio(Clip|Source|Listener|Settings|Mixer\w*)"),
        ("imageconversion", @"ImageConversion|LoadImage|EncodeToPNG|EncodeToJPG"),
        ("imgui", @"GUI|GUILayout|GUIStyle|GUIContent|GUIUtility|EditorGUILayout|EditorGUI|Event"),
        ("jsonserialize", @"JsonUtility"),
        ("particlesystem", @"ParticleSystem\w*"),
        ("physics", @"Rigidbody|Collider|BoxCollider|SphereCollider|CapsuleCollider|MeshCollider|Physics|RaycastHit|Collision"),
        ("physics2d", @"Rigidbody2D|Collider2D|Physics2D"),
        ("terrain", @"Terrain|TerrainData"),
        ("ui", @"Canvas|CanvasGroup|CanvasRenderer|RectTransformUtility"),
        ("uielements", @"VisualElement|UIDocument|UIElements"),
        ("unitywebrequest", @"UnityWebRequest|DownloadHandler\w*"),
        ("video", @"VideoPlayer|VideoClip"),
        ("vr", @"XRSettings|XRDevice"),
        ("xr", @"InputDevices?|XRNode|InputTracking|XRDisplaySubsystem"),
    };

    static readonly string[] UnityFacingFolders = { "Runtime/Unity", "Runtime/Meta", "Runtime/Interaction", "Runtime/XRHands", "Editor", "Tests/Runtime", "Samples~" };

    static Dictionary<string, string> Dependencies(string path)
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(path));
        return doc.RootElement.GetProperty("dependencies").EnumerateObject().ToDictionary(p => p.Name, p => p.Value.GetString()!);
    }

    static IEnumerable<string> Modules(Dictionary<string, string> deps) =>
        deps.Keys.Where(k => k.StartsWith("com.unity.modules.")).Select(k => k["com.unity.modules.".Length..]);

    static string CodeOnly(string source)
    {
        source = Regex.Replace(source, @"/\*.*?\*/", "", RegexOptions.Singleline);
        source = Regex.Replace(source, @"//[^\n]*", "");
        return Regex.Replace(source, "@?\"(?:\\\\.|[^\"\\\\\\n])*\"", "\"\"");
    }

    /// <summary>The modules this package's own code names a type of, each with the first file that does.</summary>
    static Dictionary<string, string> ModulesUsedByThePackage()
    {
        var used = new Dictionary<string, string>();
        foreach (string folder in UnityFacingFolders)
            foreach (string cs in Directory.EnumerateFiles(Path.Combine(Package, folder), "*.cs", SearchOption.AllDirectories))
            {
                string code = CodeOnly(File.ReadAllText(cs));
                foreach (var (module, types) in ModuleTypes)
                    if (!used.ContainsKey(module) && Regex.IsMatch(code, @"\b(" + types + @")\b"))
                        used[module] = Path.GetRelativePath(Package, cs);
            }
        return used;
    }

    [Test]
    public void TheManifestPinsTheVersionsTheDeclarationsWereTranscribedFrom()
    {
        var deps = Dependencies(Path.Combine(RepositoryRoot.Path, "Packages", "manifest.json"));
        foreach (var (name, version) in Pinned)
            Assert.That(deps.TryGetValue(name, out string? v) ? v : null, Is.EqualTo(version), name);
        string readme = File.ReadAllText(Path.Combine(RepositoryRoot.Path, "Tests", "UnityDouble", "README.md"));
        foreach (var (name, version) in Pinned)
            Assert.That(readme, Does.Contain(version), "Tests/UnityDouble/README.md cites " + name + " " + version);
    }

    [Test]
    public void TheManifestEnablesEveryModuleThePinnedPackagesAndThisPackageUse()
    {
        var enabled = Modules(Dependencies(Path.Combine(RepositoryRoot.Path, "Packages", "manifest.json"))).ToHashSet();
        var missing = UsedByPinnedPackages.Where(u => !enabled.Contains(u.Module)).Select(u => u.Module + " (" + u.Evidence + ")").ToList();
        Assert.That(missing, Is.Empty, "modules used by the pinned packages but not enabled in Packages/manifest.json");
        var own = Modules(Dependencies(Path.Combine(Package, "package.json")));
        Assert.That(enabled, Is.SupersetOf(own), "the package's own modules are enabled in the project");
        foreach (var deps in new[] { Dependencies(Path.Combine(RepositoryRoot.Path, "Packages", "manifest.json")), Dependencies(Path.Combine(Package, "package.json")) })
            foreach (var (name, version) in deps.Where(d => d.Key.StartsWith("com.unity.modules.")))
                Assert.That(version, Is.EqualTo("1.0.0"), name + ": built-in modules are version 1.0.0");
    }

    [Test]
    public void ThePackageDeclaresExactlyTheModulesItsCodeUses()
    {
        var used = ModulesUsedByThePackage();
        var declared = Modules(Dependencies(Path.Combine(Package, "package.json"))).ToHashSet();
        var undeclared = used.Where(u => !declared.Contains(u.Key)).Select(u => u.Key + " (" + u.Value + ")").ToList();
        Assert.That(undeclared, Is.Empty, "modules the package's code uses but its package.json does not declare");
        Assert.That(declared.Where(d => !used.ContainsKey(d)), Is.Empty, "modules declared in package.json that no code of the package uses");
        // What the code uses today (fails, on purpose, when that changes, so the list above is looked at again).
        Assert.That(used.Keys.OrderBy(k => k, StringComparer.Ordinal), Is.EqualTo(new[] { "imgui", "jsonserialize", "physics" }));
    }

    /// <summary>
    /// The assemblies of other packages that the package's asmdefs reference, each as named by that package's own
    /// asmdef at the pinned version.
    /// </summary>
    static readonly (string Assembly, string DeclaredIn)[] ForeignAssemblies =
    {
        ("Oculus.VR", "com.meta.xr.sdk.core 68.0.2: Oculus.VR.asmdef"),
        ("Oculus.VR.Editor", "com.meta.xr.sdk.core 68.0.2: Editor/Oculus.VR.Editor.asmdef"),
        ("Oculus.Interaction", "com.meta.xr.sdk.interaction 68.0.0: Runtime/Oculus.Interaction.asmdef"),
        ("Unity.XR.Management", "com.unity.xr.management 4.4.0: Runtime/Unity.XR.Management.asmdef"),
        ("Unity.XR.Management.Editor", "com.unity.xr.management 4.4.0: Editor/Unity.XR.Management.Editor.asmdef"),
        ("Unity.XR.Oculus", "com.unity.xr.oculus 4.2.0: Runtime/Unity.XR.Oculus.asmdef"),
        ("Unity.XR.Hands", "com.unity.xr.hands 1.5.0: Runtime/Unity.XR.Hands.asmdef"),
        ("Unity.XR.Interaction.Toolkit", "com.unity.xr.interaction.toolkit 2.5.4: Runtime/Unity.XR.Interaction.Toolkit.asmdef"),
        ("Unity.InputSystem", "com.unity.inputsystem 1.7.0 (XRI 2.5.4 depends on it) and 1.8.1 (XRI 3.0.8): InputSystem/Unity.InputSystem.asmdef"),
        ("Unity.XR.CoreUtils", "com.unity.xr.core-utils 2.2.0 (com.unity.xr.hands 1.5.0 depends on it; its Runtime/Unity.XR.Hands.asmdef references it): Runtime/Unity.XR.CoreUtils.asmdef"),
        ("UnityEngine.TestRunner", "com.unity.test-framework 1.1.33: UnityEngine.TestRunner/UnityEngine.TestRunner.asmdef"),
        ("UnityEditor.TestRunner", "com.unity.test-framework 1.1.33: UnityEditor.TestRunner/UnityEditor.TestRunner.asmdef"),
    };

    /// <summary>Packages a versionDefine may name that the manifest does not list because a pinned package pulls them in.</summary>
    static readonly (string Package, string PulledBy)[] Transitive =
    {
        ("com.meta.xr.sdk.interaction", "com.meta.xr.sdk.interaction.ovr 68.0.0 depends on com.meta.xr.sdk.interaction 68.0.0"),
    };

    [Test]
    public void AsmdefsNameRealAssembliesAndPackages()
    {
        var pinned = Dependencies(Path.Combine(RepositoryRoot.Path, "Packages", "manifest.json")).Keys.ToHashSet();
        pinned.UnionWith(Transitive.Select(t => t.Package));
        var ownNames = new HashSet<string>();
        var asmdefs = Directory.EnumerateFiles(Package, "*.asmdef", SearchOption.AllDirectories).ToList();
        foreach (string path in asmdefs)
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(path));
            ownNames.Add(doc.RootElement.GetProperty("name").GetString()!);
        }
        var foreign = ForeignAssemblies.Select(f => f.Assembly).ToHashSet();
        foreach (string path in asmdefs)
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(path));
            string rel = Path.GetRelativePath(Package, path);
            foreach (var r in doc.RootElement.GetProperty("references").EnumerateArray().Select(e => e.GetString()!))
                Assert.That(ownNames.Contains(r) || foreign.Contains(r), Is.True, rel + " references '" + r + "', an assembly of neither this package nor the list of checked foreign assemblies");
            if (doc.RootElement.TryGetProperty("versionDefines", out var defines))
                foreach (var d in defines.EnumerateArray())
                    Assert.That(pinned, Does.Contain(d.GetProperty("name").GetString()), rel + ": a versionDefine names a package the project does not install");
        }
    }

    [Test]
    public void TheModuleScanSeesAModuleInCode()
    {
        // The scan must be able to fail: a type named in code counts, the same word in a comment or a string does not.
        Assert.That(Regex.IsMatch(CodeOnly("var s = GetComponent<AudioSource>();"), @"\b(Audio(Clip|Source))\b"), Is.True);
        Assert.That(Regex.IsMatch(CodeOnly("// an AudioSource would do\nstring t = \"AudioSource\";"), @"\b(Audio(Clip|Source))\b"), Is.False);
    }
}
