using System.Text.Json;

namespace Kosmos.PseudoHaptic.UnityCompile;

/// <summary>One assembly definition (.asmdef), the fields Unity's compilation reads.</summary>
public sealed record Asmdef(
    string Name,
    string Folder,
    IReadOnlyList<string> References,
    IReadOnlyList<string> IncludePlatforms,
    IReadOnlyList<string> ExcludePlatforms,
    bool AllowUnsafeCode,
    bool OverrideReferences,
    IReadOnlyList<string> PrecompiledReferences,
    bool AutoReferenced,
    IReadOnlyList<string> DefineConstraints,
    IReadOnlyList<(string Package, string Expression, string Define)> VersionDefines,
    bool NoEngineReferences)
{
    /// <summary>Only in the editor: includePlatforms is exactly ["Editor"] (Unity's AssemblyFlags.EditorOnly).</summary>
    public bool EditorOnly => IncludePlatforms.Count == 1 && IncludePlatforms[0] == "Editor";

    /// <summary>A test assembly: one of its define constraints is UNITY_INCLUDE_TESTS.</summary>
    public bool IsTestAssembly => DefineConstraints.Contains("UNITY_INCLUDE_TESTS");

    public static Asmdef Read(string path)
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(path), new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
        JsonElement r = doc.RootElement;
        IReadOnlyList<string> Strings(string name) =>
            r.TryGetProperty(name, out JsonElement a) ? a.EnumerateArray().Select(e => e.GetString()!).ToList() : new List<string>();
        bool Bool(string name, bool fallback) => r.TryGetProperty(name, out JsonElement b) ? b.GetBoolean() : fallback;
        var versionDefines = r.TryGetProperty("versionDefines", out JsonElement vd)
            ? vd.EnumerateArray().Select(e => (e.GetProperty("name").GetString()!, e.TryGetProperty("expression", out JsonElement x) ? x.GetString() ?? "" : "", e.GetProperty("define").GetString()!)).ToList()
            : new List<(string, string, string)>();
        return new Asmdef(r.GetProperty("name").GetString()!, Path.GetDirectoryName(path)!, Strings("references"), Strings("includePlatforms"),
            Strings("excludePlatforms"), Bool("allowUnsafeCode", false), Bool("overrideReferences", false), Strings("precompiledReferences"),
            Bool("autoReferenced", true), Strings("defineConstraints"), versionDefines, Bool("noEngineReferences", false));
    }
}
