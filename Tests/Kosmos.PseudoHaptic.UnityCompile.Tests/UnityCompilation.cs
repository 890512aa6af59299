using System.Collections.Immutable;
using System.Reflection;
using System.Text.Json;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace Kosmos.PseudoHaptic.UnityCompile;

/// <summary>What one build compiled: the diagnostics of each assembly, and the asmdefs left out and why.</summary>
public sealed class BuildResult
{
    public Dictionary<string, ImmutableArray<Diagnostic>> Compiled { get; } = new();
    public Dictionary<string, string> LeftOut { get; } = new();
    public List<string> Warnings { get; } = new();

    public IEnumerable<string> Problems(DiagnosticSeverity atLeast) =>
        Compiled.SelectMany(kv => kv.Value.Where(d => d.Severity >= atLeast && !d.IsSuppressed).Select(d => kv.Key + ": " + d));
}

/// <summary>
/// Unity's script compilation, per asmdef (UnityCsReference 2022.3, Editor/Mono/Scripting/ScriptCompilation:
/// CustomScriptAssembly.IsCompatibleWith, EditorBuildRules.AddScriptAssemblyReferences, EditorCompilation.GetTargetAssemblyDefines),
/// for one <see cref="UnityTarget"/>:
/// <list type="bullet">
/// <item>an asmdef compiles when its platforms allow the target (includePlatforms/excludePlatforms; "Editor" only in the
/// editor), its defineConstraints hold over the target's symbols plus its own versionDefines (evaluated against the
/// project's package versions and the editor version), and, for a test assembly, when the target is the editor and its
/// package is testable;</item>
/// <item>its sources are the .cs files under its folder no nested asmdef claims; its symbols are the target's (the
/// .NET Framework profile for editor-only ones) plus its versionDefines;</item>
/// <item>it references exactly: the assemblies it names that this build compiles (the package's, by name, and the
/// double's, ../UnityDouble/assemblies.json; a name not available is dropped, as Unity drops it, so the code that needs
/// it fails); UnityEngine, and in the editor UnityEditor, unless noEngineReferences; with overrideReferences only the
/// precompiled DLLs it lists, otherwise the auto-referenced ones (Newtonsoft.Json); for an editor-only assembly the
/// Test Framework and NUnit as well (Unity adds them to those); and .NET Standard 2.1;</item>
/// <item>the samples (Samples~, no asmdef) compile as Assembly-CSharp against every auto-referenced assembly.</item>
/// </list>
/// C# 9, as Unity 2022.3's compiler. The double's assemblies are compiled from their folders, under their real names, once
/// per set of their own versionDefines (assemblies.json: a folder may declare two versions of a package, e.g. XRI 2.5.4 and,
/// with XRI_3, 3.0.8), chosen by the project's package versions as an asmdef's versionDefines are.
/// </summary>
public static class UnityCompilation
{
    static readonly CSharpParseOptions Parse9 = new(LanguageVersion.CSharp9);
    static readonly string DoubleFolder = Path.Combine(UnityProject.FindRoot(), "Tests", "UnityDouble");

    sealed record DoubleAssembly(string Name, bool Unity, bool EditorOnly, bool AutoReferenced, MetadataReference Reference);

    static readonly Lazy<MetadataReference> NetStandard = new(() =>
    {
        string path = typeof(UnityCompilation).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>().First(a => a.Key == "NetStandardReference").Value!;
        return MetadataReference.CreateFromFile(path);
    });

    /// <summary>Unity's precompiled DLLs the asmdefs can name, and whether Unity references each by default.</summary>
    static readonly Lazy<Dictionary<string, (MetadataReference Reference, bool AutoReferenced)>> Precompiled = new(() => new()
    {
        ["nunit.framework.dll"] = (MetadataReference.CreateFromFile(typeof(NUnit.Framework.Assert).Assembly.Location), false),
        ["Newtonsoft.Json.dll"] = (MetadataReference.CreateFromFile(typeof(Newtonsoft.Json.JsonConvert).Assembly.Location), true),
    });

    /// <summary>The double compiled once per set of its own version defines (a folder may hold two versions' declarations).</summary>
    static readonly System.Collections.Concurrent.ConcurrentDictionary<string, Lazy<IReadOnlyList<DoubleAssembly>>> DoublesByDefines = new();

    /// <summary>The double's assemblies for a project with these package versions (their versionDefines, as an asmdef's).</summary>
    static IReadOnlyList<DoubleAssembly> Doubles(IReadOnlyDictionary<string, string> packageVersions)
    {
        var defines = DoubleDefines(packageVersions);
        string key = string.Join(";", defines.OrderBy(kv => kv.Key, StringComparer.Ordinal).Select(kv => kv.Key + "=" + string.Join(",", kv.Value.OrderBy(d => d, StringComparer.Ordinal))));
        return DoublesByDefines.GetOrAdd(key, _ => new Lazy<IReadOnlyList<DoubleAssembly>>(() => CompileDouble(defines))).Value;
    }

    /// <summary>Per double assembly, the defines of its versionDefines that hold for <paramref name="packageVersions"/>.</summary>
    public static Dictionary<string, List<string>> DoubleDefines(IReadOnlyDictionary<string, string> packageVersions)
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(DoubleFolder, "assemblies.json")));
        var result = new Dictionary<string, List<string>>();
        foreach (JsonElement a in doc.RootElement.GetProperty("assemblies").EnumerateArray())
        {
            var list = new List<string>();
            if (a.TryGetProperty("versionDefines", out JsonElement vd))
                foreach (JsonElement d in vd.EnumerateArray())
                    if (packageVersions.TryGetValue(d.GetProperty("name").GetString()!, out string? version) && VersionExpression.Matches(d.GetProperty("expression").GetString()!, version))
                        list.Add(d.GetProperty("define").GetString()!);
            result[a.GetProperty("name").GetString()!] = list;
        }
        return result;
    }

    /// <summary>Compiles the double's folders, each as its named assembly with its defines; throws if one does not compile.</summary>
    static IReadOnlyList<DoubleAssembly> CompileDouble(Dictionary<string, List<string>> defines)
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(DoubleFolder, "assemblies.json")));
        var built = new Dictionary<string, MetadataReference>();
        var list = new List<DoubleAssembly>();
        foreach (JsonElement a in doc.RootElement.GetProperty("assemblies").EnumerateArray())
        {
            string name = a.GetProperty("name").GetString()!;
            var refs = new List<MetadataReference> { NetStandard.Value };
            if (a.TryGetProperty("references", out JsonElement r)) refs.AddRange(r.EnumerateArray().Select(e => built[e.GetString()!]));
            if (a.TryGetProperty("precompiledReferences", out JsonElement p)) refs.AddRange(p.EnumerateArray().Select(e => Precompiled.Value[e.GetString()!].Reference));
            var parse = Parse9.WithPreprocessorSymbols(defines.TryGetValue(name, out var own) ? own : new List<string>());
            var trees = Directory.EnumerateFiles(Path.Combine(DoubleFolder, name), "*.cs", SearchOption.AllDirectories)
                .Select(f => CSharpSyntaxTree.ParseText(File.ReadAllText(f), parse, f)).ToList();
            var compilation = CSharpCompilation.Create(name, trees, refs, Options(allowUnsafe: false));
            var errors = compilation.GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error).ToList();
            if (errors.Count > 0) throw new InvalidOperationException("the double's " + name + " does not compile:\n" + string.Join("\n", errors));
            built[name] = compilation.ToMetadataReference();
            list.Add(new DoubleAssembly(name, a.TryGetProperty("unity", out JsonElement u) && u.GetBoolean(),
                a.TryGetProperty("editorOnly", out JsonElement eo) && eo.GetBoolean(),
                !a.TryGetProperty("autoReferenced", out JsonElement ar) || ar.GetBoolean(), built[name]));
        }
        return list;
    }

    // CS1701/CS1702 (a reference's netstandard 2.0 unified with 2.1) are what every .NET build silences too.
    static CSharpCompilationOptions Options(bool allowUnsafe) =>
        new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, allowUnsafe: allowUnsafe, nullableContextOptions: NullableContextOptions.Disable, warningLevel: 4)
            .WithSpecificDiagnosticOptions(new Dictionary<string, ReportDiagnostic> { ["CS1701"] = ReportDiagnostic.Suppress, ["CS1702"] = ReportDiagnostic.Suppress });

    /// <summary>Compiles the project's asmdefs for <paramref name="target"/>; <paramref name="edit"/> may change an asmdef first (tests of the check itself).</summary>
    public static BuildResult Build(UnityProject project, UnityTarget target, Func<Asmdef, Asmdef>? edit = null, IReadOnlyDictionary<string, string>? replaceSources = null)
    {
        var result = new BuildResult();
        bool editor = target == UnityTarget.EditorAndroid;
        var allDoubles = Doubles(project.PackageVersions);
        var doubles = allDoubles.Where(d => editor || !d.EditorOnly).ToList();
        var asmdefs = project.Asmdefs().Select(a => edit != null ? edit(a) : a).ToList();

        // Which asmdefs this build compiles, each with its symbols.
        var symbols = new Dictionary<string, HashSet<string>>();
        foreach (Asmdef a in asmdefs)
        {
            var defines = ScriptingSymbols.For(target, project.UnityVersion, a.EditorOnly);
            foreach (var (package, expression, define) in a.VersionDefines)
            {
                if (!project.PackageVersions.TryGetValue(package, out string? version)) continue;
                try
                {
                    if (expression.Length == 0 || VersionExpression.Matches(expression, version)) defines.Add(define);
                }
                catch (FormatException e)
                {
                    result.Warnings.Add(a.Name + ": versionDefine " + define + ": " + e.Message);
                }
            }
            string? why = !Platforms(a, editor) ? "its platforms exclude this build"
                : a.IsTestAssembly && !editor ? "a test assembly outside the editor"
                : a.IsTestAssembly && !project.Testables.Contains(UnityProject.PackageName) ? "a test assembly of a package not in testables"
                : !DefineConstraints.Hold(defines, a.DefineConstraints) ? "defineConstraints " + string.Join(", ", a.DefineConstraints) + " do not hold"
                : null;
            if (why != null) result.LeftOut[a.Name] = why;
            else symbols[a.Name] = defines;
        }

        var compiled = new Dictionary<string, MetadataReference>();
        var byName = asmdefs.Where(a => symbols.ContainsKey(a.Name)).ToDictionary(a => a.Name);
        var pending = new List<Asmdef>(byName.Values);
        while (pending.Count > 0)
        {
            Asmdef? next = pending.FirstOrDefault(a => a.References.All(r => !byName.ContainsKey(r) || compiled.ContainsKey(r)));
            if (next == null) throw new InvalidOperationException("a reference cycle among " + string.Join(", ", pending.Select(p => p.Name)));
            pending.Remove(next);
            var refs = new List<MetadataReference> { NetStandard.Value };
            if (!next.NoEngineReferences)
                refs.AddRange(doubles.Where(d => d.Unity && (editor || !d.EditorOnly)).Select(d => d.Reference));
            foreach (string r in next.References)
            {
                if (compiled.TryGetValue(r, out MetadataReference? own)) refs.Add(own);
                else if (doubles.FirstOrDefault(d => d.Name == r && !d.Unity) is { } foreign) refs.Add(foreign.Reference);
                else if (!asmdefs.Any(a => a.Name == r) && !allDoubles.Any(d => d.Name == r)) result.Warnings.Add(next.Name + ": references '" + r + "', which no assembly is named");
            }
            foreach (var (dll, (reference, auto)) in Precompiled.Value)
                if (next.OverrideReferences ? next.PrecompiledReferences.Contains(dll) : auto) refs.Add(reference);
            if (next.EditorOnly && editor)
            {
                // Unity gives editor-only assemblies the Test Framework and NUnit (TestRunnerHelpers).
                refs.AddRange(doubles.Where(d => d.Name is "UnityEngine.TestRunner" or "UnityEditor.TestRunner").Select(d => d.Reference));
                refs.Add(Precompiled.Value["nunit.framework.dll"].Reference);
            }
            var sources = UnityProject.SourcesOf(next.Folder);
            compiled[next.Name] = Compile(next.Name, sources, symbols[next.Name], refs.Distinct().ToList(), next.AllowUnsafeCode, result, replaceSources);
        }

        // The samples, imported into Assets: Assembly-CSharp, which references every auto-referenced assembly.
        var sampleRefs = new List<MetadataReference> { NetStandard.Value };
        sampleRefs.AddRange(doubles.Where(d => d.Unity || d.AutoReferenced).Select(d => d.Reference));
        sampleRefs.AddRange(byName.Values.Where(a => a.AutoReferenced).Select(a => compiled[a.Name]));
        sampleRefs.AddRange(Precompiled.Value.Values.Where(p => p.AutoReferenced).Select(p => p.Reference));
        Compile("Assembly-CSharp", project.SampleSources(), ScriptingSymbols.For(target, project.UnityVersion, false), sampleRefs, false, result, replaceSources);
        return result;
    }

    static bool Platforms(Asmdef a, bool editor)
    {
        const string platform = "Android";
        string here = editor ? "Editor" : platform;
        if (a.ExcludePlatforms.Count > 0) return !a.ExcludePlatforms.Contains(here);
        if (a.IncludePlatforms.Count > 0) return a.IncludePlatforms.Contains(here);
        return true;
    }

    static MetadataReference Compile(string name, IReadOnlyList<string> files, IEnumerable<string> defines, List<MetadataReference> refs, bool allowUnsafe,
                                     BuildResult result, IReadOnlyDictionary<string, string>? replaceSources)
    {
        var options = Parse9.WithPreprocessorSymbols(defines);
        var trees = files.Select(f => CSharpSyntaxTree.ParseText(replaceSources != null && replaceSources.TryGetValue(Path.GetFileName(f), out string? text) ? text : File.ReadAllText(f), options, f)).ToList();
        var compilation = CSharpCompilation.Create(name, trees, refs, Options(allowUnsafe));
        result.Compiled[name] = compilation.GetDiagnostics();
        return compilation.ToMetadataReference();
    }
}
