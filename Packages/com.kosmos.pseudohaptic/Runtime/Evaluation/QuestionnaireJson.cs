using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Reads questionnaire definitions from JSON (the package's Runtime/Evaluation/Questionnaires/*.json, or a
    /// translated copy): { "id", "title", "instructions"?, "scale": { "min", "max", "minLabel"?, "maxLabel"? },
    /// "items": [ { "number", "text", "reverse"? } ] }. Unknown properties are ignored; anything missing,
    /// mistyped or inconsistent throws <see cref="EvaluationFormatException"/> naming the line.
    /// Walks the JSON tree by hand (no reflection), so nothing is lost to IL2CPP stripping.
    /// </summary>
    public static class QuestionnaireJson
    {
        /// <summary>Parses one definition; <paramref name="sourceName"/> labels errors.</summary>
        public static Questionnaire Parse(string json, string sourceName)
        {
            if (json == null) throw new ArgumentNullException(nameof(json));
            JToken root;
            try
            {
                root = JToken.Parse(json, new JsonLoadSettings
                {
                    LineInfoHandling = LineInfoHandling.Load,
                    DuplicatePropertyNameHandling = DuplicatePropertyNameHandling.Error,
                    CommentHandling = CommentHandling.Ignore,
                });
            }
            catch (JsonReaderException e)
            {
                throw new EvaluationFormatException(sourceName, e.LineNumber, "not valid JSON: " + FirstSentence(e.Message));
            }

            var obj = root as JObject;
            if (obj == null) throw Fail(sourceName, root, "expected a JSON object { \"id\", \"title\", \"scale\", \"items\" }");

            string id = RequiredString(obj, "id", sourceName);
            string title = OptionalString(obj, "title", sourceName) ?? id;
            string instructions = OptionalString(obj, "instructions", sourceName) ?? "";

            var scale = Required(obj, "scale", sourceName) as JObject;
            if (scale == null) throw Fail(sourceName, obj["scale"], "\"scale\" must be an object { \"min\", \"max\" }");
            int min = RequiredInt(scale, "min", sourceName);
            int max = RequiredInt(scale, "max", sourceName);
            if (min >= max) throw Fail(sourceName, scale, "scale min " + min + " must be below max " + max);
            string minLabel = OptionalString(scale, "minLabel", sourceName) ?? "";
            string maxLabel = OptionalString(scale, "maxLabel", sourceName) ?? "";

            var itemsArray = Required(obj, "items", sourceName) as JArray;
            if (itemsArray == null) throw Fail(sourceName, obj["items"], "\"items\" must be an array");
            if (itemsArray.Count == 0) throw Fail(sourceName, itemsArray, "\"items\" is empty");

            var items = new List<QuestionnaireItem>(itemsArray.Count);
            var seen = new HashSet<int>();
            foreach (var token in itemsArray)
            {
                var itemObj = token as JObject;
                if (itemObj == null) throw Fail(sourceName, token, "each item must be an object { \"number\", \"text\", \"reverse\" }");
                int number = RequiredInt(itemObj, "number", sourceName);
                if (number < 1) throw Fail(sourceName, itemObj["number"], "item number " + number + " is below 1");
                if (!seen.Add(number)) throw Fail(sourceName, itemObj["number"], "item number " + number + " appears twice");
                string text = RequiredString(itemObj, "text", sourceName);
                bool reverse = OptionalBool(itemObj, "reverse", sourceName);
                items.Add(new QuestionnaireItem(number, text, reverse));
            }

            try
            {
                return new Questionnaire(id, title, min, max, items, instructions, minLabel, maxLabel);
            }
            catch (ArgumentException e)
            {
                throw Fail(sourceName, obj, e.Message);
            }
        }

        /// <summary>Reads one definition file.</summary>
        public static Questionnaire LoadFile(string path) => Parse(File.ReadAllText(path), path);

        /// <summary>
        /// Reads every *.json in a folder: the default parts first in report order
        /// (<see cref="QuestionnaireCatalog.DefaultFileNames"/>), then any others by file name.
        /// </summary>
        public static QuestionnaireCatalog LoadDirectory(string directory)
        {
            if (!Directory.Exists(directory))
                throw new EvaluationFormatException(directory, 0, "questionnaire folder not found");
            var files = new List<string>(Directory.GetFiles(directory, "*.json"));
            files.Sort(StringComparer.Ordinal);
            var ordered = new List<string>();
            foreach (var name in QuestionnaireCatalog.DefaultFileNames)
            {
                string path = Path.Combine(directory, name);
                int at = files.FindIndex(f => string.Equals(Path.GetFileName(f), name, StringComparison.Ordinal));
                if (at >= 0) { ordered.Add(path); files.RemoveAt(at); }
            }
            ordered.AddRange(files);
            if (ordered.Count == 0) throw new EvaluationFormatException(directory, 0, "no *.json questionnaire definitions");

            var parts = new List<Questionnaire>(ordered.Count);
            foreach (var path in ordered) parts.Add(LoadFile(path));
            return Catalog(parts, ordered, directory);
        }

        /// <summary>A catalog from (name, JSON text) pairs in report order, e.g. embedded copies of the package's files.</summary>
        public static QuestionnaireCatalog ParseAll(IEnumerable<KeyValuePair<string, string>> namedJson)
        {
            if (namedJson == null) throw new ArgumentNullException(nameof(namedJson));
            var parts = new List<Questionnaire>();
            var sources = new List<string>();
            foreach (var pair in namedJson)
            {
                parts.Add(Parse(pair.Value, pair.Key));
                sources.Add(pair.Key);
            }
            return Catalog(parts, sources, "questionnaires");
        }

        /// <summary>The catalog of <paramref name="parts"/>, read from <paramref name="sources"/> (one each); an id given twice is
        /// refused naming the definition that repeats it and the one that gave it first (a study with two copies of a file).</summary>
        static QuestionnaireCatalog Catalog(List<Questionnaire> parts, List<string> sources, string sourceName)
        {
            for (int i = 1; i < parts.Count; i++)
                for (int j = 0; j < i; j++)
                    if (string.Equals(parts[i].Id, parts[j].Id, StringComparison.Ordinal))
                        throw new EvaluationFormatException(sources[i], 0, "questionnaire id '" + parts[i].Id + "' is already defined in " + sources[j]);
            try { return new QuestionnaireCatalog(parts); }
            catch (ArgumentException e) { throw new EvaluationFormatException(sourceName, 0, e.Message); }
        }

        static JToken Required(JObject obj, string name, string sourceName)
        {
            JToken value = obj[name];
            if (value == null || value.Type == JTokenType.Null) throw Fail(sourceName, obj, "missing \"" + name + "\"");
            return value;
        }

        static string RequiredString(JObject obj, string name, string sourceName)
        {
            JToken value = Required(obj, name, sourceName);
            if (value.Type != JTokenType.String) throw Fail(sourceName, value, "\"" + name + "\" must be a string");
            string s = (string)value;
            if (string.IsNullOrWhiteSpace(s)) throw Fail(sourceName, value, "\"" + name + "\" is empty");
            return s;
        }

        static string OptionalString(JObject obj, string name, string sourceName)
        {
            JToken value = obj[name];
            if (value == null || value.Type == JTokenType.Null) return null;
            if (value.Type != JTokenType.String) throw Fail(sourceName, value, "\"" + name + "\" must be a string");
            return (string)value;
        }

        static int RequiredInt(JObject obj, string name, string sourceName)
        {
            JToken value = Required(obj, name, sourceName);
            if (value.Type != JTokenType.Integer) throw Fail(sourceName, value, "\"" + name + "\" must be a whole number");
            long n;
            try { n = (long)value; }
            catch (OverflowException) { throw Fail(sourceName, value, "\"" + name + "\" is too large"); }
            if (n < int.MinValue || n > int.MaxValue) throw Fail(sourceName, value, "\"" + name + "\" is too large");
            return (int)n;
        }

        static bool OptionalBool(JObject obj, string name, string sourceName)
        {
            JToken value = obj[name];
            if (value == null || value.Type == JTokenType.Null) return false;
            if (value.Type != JTokenType.Boolean) throw Fail(sourceName, value, "\"" + name + "\" must be true or false");
            return (bool)value;
        }

        static EvaluationFormatException Fail(string sourceName, JToken at, string reason)
        {
            var info = at as IJsonLineInfo;
            int line = info != null && info.HasLineInfo() ? info.LineNumber : 0;
            return new EvaluationFormatException(sourceName, line, reason);
        }

        static string FirstSentence(string message)
        {
            // Newtonsoft appends "Path '…', line N, position M." — the line is reported separately.
            int cut = message.IndexOf(" Path '", StringComparison.Ordinal);
            if (cut < 0) cut = message.IndexOf(", line ", StringComparison.Ordinal);
            return cut > 0 ? message.Substring(0, cut).TrimEnd('.', ' ') : message;
        }
    }
}
