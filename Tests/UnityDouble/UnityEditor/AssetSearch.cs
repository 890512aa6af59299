// Test double of AssetDatabase.FindAssets(string) and GUIDToAssetPath(string) (UnityCsReference 2022.3,
// Modules/AssetDatabase/Editor/ScriptBindings/AssetDatabase.bindings.cs and Editor/Mono/AssetDatabase/AssetDatabaseSearching.cs),
// over the double's in-memory assets: a filter of words, each of which must appear in the asset's file name (any case),
// and "t:Prefab" (prefab assets: a .prefab path) or "t:ClassName" (assets of that class, a ScriptableObject's included), as
// Unity's search filter reads them. GUIDs are made up per path.
using System;
using System.Collections.Generic;

namespace UnityEditor
{
    public sealed partial class AssetDatabase
    {
        static readonly Dictionary<string, string> s_guidOfPath = new Dictionary<string, string>();
        static readonly Dictionary<string, string> s_pathOfGuid = new Dictionary<string, string>();

        public static string[] FindAssets(string filter)
        {
            var words = new List<string>();
            string type = null;
            foreach (string token in (filter ?? "").Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries))
                if (token.StartsWith("t:", StringComparison.OrdinalIgnoreCase)) type = token.Substring(2);
                else words.Add(token);
            var found = new List<string>();
            foreach (string path in Assets.Keys)
            {
                if (type != null && !(type.Equals("Prefab", StringComparison.OrdinalIgnoreCase) ? path.EndsWith(".prefab", StringComparison.OrdinalIgnoreCase)
                        : Assets[path] != null && Assets[path].GetType().Name.Equals(type, StringComparison.OrdinalIgnoreCase))) continue;
                string file = System.IO.Path.GetFileNameWithoutExtension(path);
                if (!words.TrueForAll(w => file.IndexOf(w, StringComparison.OrdinalIgnoreCase) >= 0)) continue;
                found.Add(GuidOf(path));
            }
            found.Sort(StringComparer.Ordinal);
            return found.ToArray();
        }

        public static string GUIDToAssetPath(string guid) => guid != null && s_pathOfGuid.TryGetValue(guid, out string path) ? path : "";

        static string GuidOf(string path)
        {
            if (s_guidOfPath.TryGetValue(path, out string guid)) return guid;
            guid = Guid.NewGuid().ToString("N");
            s_guidOfPath[path] = guid;
            s_pathOfGuid[guid] = path;
            return guid;
        }
    }
}
