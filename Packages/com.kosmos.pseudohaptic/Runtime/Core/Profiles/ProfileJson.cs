using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A <see cref="WeightProfile"/> as a file: one format for the tool (<c>pseudohaptic profiles --show NAME --json</c>,
    /// <c>--profile FILE.json</c>) and the Unity asset's export. The effects in the order the frame flows through them, each
    /// with every setting its <see cref="EffectDescriptor"/> declares, the safety limits, and the hand filter if any:
    /// <code>
    /// { "format": 1, "name": "paper",
    ///   "effects": [ { "effect": "tracking-loss-hold", "settleTime": 0.16, "requireHighConfidence": true }, … ],
    ///   "limits": { "maxGain": 3, … } }
    /// </code>
    /// Reading: a setting left out takes its default; an unknown effect, setting or key, a bad value, or a duplicate is an
    /// error (<see cref="ProfileFormatException"/>: the source and line, the effect and the setting). A file that describes
    /// a named profile exactly reads as that profile (the same instance), so a host that runs <c>paper-literal</c> with its
    /// own solver runs the file so too. Numbers are written round-trip: read back, each is the same double.
    /// </summary>
    public static class ProfileJson
    {
        public const int Format = 1;

        /// <summary>The one hand filter a profile file names (the paper's 1 s window); a profile with another cannot be written.</summary>
        public const string OneSecondAverageName = "one-second-average";

        public static string Write(WeightProfile profile)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            var sb = new StringBuilder();
            sb.Append("{\n  \"format\": ").Append(Format).Append(",\n  \"name\": ");
            Str(sb, profile.Name);
            sb.Append(",\n  \"effects\": [");
            var effects = profile.Effects;
            for (int k = 0; k < effects.Count; k++)
            {
                var d = EffectRegistry.Of(effects[k]);
                var s = d.SettingsOf(effects[k]);
                sb.Append(k == 0 ? "\n" : ",\n").Append("    { \"effect\": ");
                Str(sb, d.Name);
                for (int i = 0; i < s.Count; i++)
                {
                    sb.Append(", ");
                    Str(sb, d.Settings[i].Name);
                    sb.Append(": ").Append(d.Settings[i].Format(s[i]));
                }
                sb.Append(" }");
            }
            sb.Append(effects.Count == 0 ? "],\n" : "\n  ],\n");
            sb.Append("  \"limits\": {");
            for (int i = 0; i < SolverLimits.Settings.Count; i++)
            {
                var l = SolverLimits.Settings[i];
                sb.Append(i == 0 ? " " : ", ");
                Str(sb, l.Name);
                sb.Append(": ").Append(l.Format(l.Read(profile.Limits)));
            }
            sb.Append(" }");
            if (profile.HandFilter != null)
            {
                if (!(profile.HandFilter is OneSecondAverage avg) || avg.Window != 1 || avg.Capacity != new OneSecondAverage().Capacity)
                    throw new ArgumentException("profile '" + profile.Name + "': its hand filter '" + profile.HandFilter.Name + "' cannot be written to a profile file (only '" + OneSecondAverageName + "').", nameof(profile));
                sb.Append(",\n  \"handFilter\": ");
                Str(sb, OneSecondAverageName);
            }
            sb.Append("\n}\n");
            return sb.ToString();
        }

        /// <summary>Reads a profile file's text; <paramref name="source"/> (a path) starts every error message.</summary>
        public static WeightProfile Read(string json, string source)
        {
            if (json == null) throw new ArgumentNullException(nameof(json));
            source = string.IsNullOrEmpty(source) ? "profile" : source;
            var root = new Parser(json, source).Document();
            if (root.Kind != Kind.Object) throw Error(source, root.Line, "a profile file is a JSON object");
            string name = null;
            bool sawFormat = false, sawEffects = false;
            var effects = new List<WeightEffect>();
            var limits = SolverLimits.Default;
            IHandFilter filter = null;
            foreach (var m in root.Members)
            {
                switch (m.Key)
                {
                    case "format":
                        if (m.Value.Kind != Kind.Number || m.Value.Number != Format)
                            throw Error(source, m.Value.Line, "format: this version reads format " + Format + ", got " + m.Value);
                        sawFormat = true;
                        break;
                    case "name":
                        if (m.Value.Kind != Kind.String || string.IsNullOrWhiteSpace(m.Value.Text)) throw Error(source, m.Value.Line, "name: must be a non-empty string");
                        name = m.Value.Text;
                        break;
                    case "effects":
                        if (m.Value.Kind != Kind.Array) throw Error(source, m.Value.Line, "effects: must be a list of effects");
                        foreach (var item in m.Value.Items) effects.Add(ReadEffect(item, source, effects));
                        sawEffects = true;
                        break;
                    case "limits":
                        limits = ReadLimits(m.Value, source);
                        break;
                    case "handFilter":
                        if (m.Value.Kind == Kind.Null) break;
                        if (m.Value.Kind != Kind.String || m.Value.Text != OneSecondAverageName)
                            throw Error(source, m.Value.Line, "handFilter: must be \"" + OneSecondAverageName + "\" or null, got " + m.Value);
                        filter = new OneSecondAverage();
                        break;
                    default:
                        throw Error(source, m.Value.Line, "unknown key '" + m.Key + "'; a profile has format, name, effects, limits, handFilter");
                }
            }
            if (!sawFormat) throw Error(source, root.Line, "format: missing (write \"format\": " + Format + ")");
            if (name == null) throw Error(source, root.Line, "name: missing");
            if (!sawEffects) throw Error(source, root.Line, "effects: missing");
            var profile = new WeightProfile(name, effects, limits, filter);
            string canonical = Write(profile);
            foreach (string named in NamedProfiles.Names)
            {
                var p = NamedProfiles.Get(named);
                if (Write(p) == canonical) return p;
            }
            return profile;
        }

        static WeightEffect ReadEffect(Value item, string source, List<WeightEffect> before)
        {
            if (item.Kind != Kind.Object) throw Error(source, item.Line, "effects: each effect is an object with \"effect\": NAME and its settings");
            Value nameValue = null;
            foreach (var m in item.Members) if (m.Key == "effect") nameValue = m.Value;
            if (nameValue == null || nameValue.Kind != Kind.String) throw Error(source, item.Line, "effects: an effect without \"effect\": NAME");
            var d = EffectRegistry.Find(nameValue.Text);
            if (d == null) throw Error(source, nameValue.Line, "effect '" + nameValue.Text + "' is unknown; known effects: " + Known());
            foreach (var e in before)
                if (e.Name == d.Name) throw Error(source, nameValue.Line, "effect '" + d.Name + "' is listed twice");
            // A key given twice is refused by the reader ("key '…' given twice"), so each setting is set at most once here.
            var s = d.DefaultSettings();
            int lastLine = item.Line;
            foreach (var m in item.Members)
            {
                if (m.Key == "effect") continue;
                int i = s.IndexOf(m.Key);
                if (i < 0) throw Error(source, m.Value.Line, "effect '" + d.Name + "': unknown setting '" + m.Key + "'; its settings: " + d.SettingNames());
                s[i] = SettingValue(d.Settings[i], m.Value, source, "effect '" + d.Name + "': setting '" + m.Key + "'");
                lastLine = m.Value.Line;
            }
            try { return d.Create(s); }
            catch (ArgumentException e) { throw Error(source, LineOf(item, e.ParamName, lastLine), e.Message); }
        }

        static SolverLimits ReadLimits(Value v, string source)
        {
            if (v.Kind != Kind.Object) throw Error(source, v.Line, "limits: must be an object");
            var settings = SolverLimits.Settings;
            var values = new double[settings.Count];
            for (int i = 0; i < values.Length; i++) values[i] = settings[i].Default;
            foreach (var m in v.Members) // each key once (the reader refuses a key given twice)
            {
                int i = -1;
                for (int k = 0; k < settings.Count; k++) if (settings[k].Name == m.Key) i = k;
                if (i < 0) throw Error(source, m.Value.Line, "limits: unknown setting '" + m.Key + "'");
                values[i] = SettingValue(settings[i], m.Value, source, "limits: setting '" + m.Key + "'");
                try { settings[i].Check(values[i]); }
                catch (ArgumentException e) { throw Error(source, m.Value.Line, "limits: setting '" + m.Key + "': " + EffectDescriptor.FirstLine(e.Message)); }
            }
            return new SolverLimits(values[0], values[1], values[2], values[3], values[4]);
        }

        static double SettingValue(SettingDescriptor setting, Value v, string source, string what)
        {
            if (setting.Kind == SettingKind.Boolean)
            {
                if (v.Kind != Kind.Boolean) throw Error(source, v.Line, what + ": must be true or false, got " + v);
                return v.Flag ? 1 : 0;
            }
            if (v.Kind != Kind.Number) throw Error(source, v.Line, what + ": must be a number (" + setting.Unit + "), got " + v);
            return v.Number;
        }

        static int LineOf(Value item, string key, int fallback)
        {
            if (key != null)
                foreach (var m in item.Members)
                    if (m.Key == key) return m.Value.Line;
            return fallback;
        }

        static string Known()
        {
            var names = new List<string>();
            foreach (var d in EffectRegistry.All) names.Add(d.Name);
            return string.Join(", ", names);
        }

        static ProfileFormatException Error(string source, int line, string message)
            => new ProfileFormatException(source + ":" + line.ToString(CultureInfo.InvariantCulture) + ": " + message.TrimEnd('.'), source, line);

        static void Str(StringBuilder sb, string s)
        {
            sb.Append('"');
            foreach (char c in s)
            {
                if (c == '"' || c == '\\') sb.Append('\\').Append(c);
                else if (c < ' ') sb.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                else sb.Append(c);
            }
            sb.Append('"');
        }

        // ---- a small JSON reader that remembers each value's line ---------------------------------------------------------

        enum Kind { Null, Boolean, Number, String, Array, Object }

        sealed class Value
        {
            public Kind Kind;
            public int Line;
            public double Number;
            public bool Flag;
            public string Text;
            public List<Value> Items;
            public List<KeyValuePair<string, Value>> Members;

            public override string ToString()
            {
                switch (Kind)
                {
                    case Kind.Null: return "null";
                    case Kind.Boolean: return Flag ? "true" : "false";
                    case Kind.Number: return Number.ToString("R", CultureInfo.InvariantCulture);
                    case Kind.String: return "\"" + Text + "\"";
                    case Kind.Array: return "a list";
                    default: return "an object";
                }
            }
        }

        sealed class Parser
        {
            readonly string _s;
            readonly string _source;
            int _i;
            int _line = 1;

            public Parser(string s, string source) { _s = s; _source = source; }

            public Value Document()
            {
                if (_s.Length > 0 && _s[0] == '\uFEFF') _i = 1;
                var v = Parse(0);
                Skip();
                if (_i < _s.Length) throw Fail("text after the profile's closing brace");
                return v;
            }

            ProfileFormatException Fail(string what) => Error(_source, _line, "not valid JSON: " + what);

            void Skip()
            {
                while (_i < _s.Length)
                {
                    char c = _s[_i];
                    if (c == '\n') { _line++; _i++; }
                    else if (c == ' ' || c == '\t' || c == '\r') _i++;
                    else break;
                }
            }

            Value Parse(int depth)
            {
                if (depth > 64) throw Fail("nested too deeply");
                Skip();
                if (_i >= _s.Length) throw Fail("the text ends where a value was expected");
                var v = new Value { Line = _line };
                char c = _s[_i];
                if (c == '{')
                {
                    _i++;
                    v.Kind = Kind.Object;
                    v.Members = new List<KeyValuePair<string, Value>>();
                    Skip();
                    if (_i < _s.Length && _s[_i] == '}') { _i++; return v; }
                    while (true)
                    {
                        Skip();
                        if (_i >= _s.Length || _s[_i] != '"') throw Fail("expected a quoted key");
                        string key = ParseString();
                        foreach (var m in v.Members)
                            if (m.Key == key) throw Fail("key '" + key + "' given twice");
                        Skip();
                        if (_i >= _s.Length || _s[_i] != ':') throw Fail("expected ':' after \"" + key + "\"");
                        _i++;
                        v.Members.Add(new KeyValuePair<string, Value>(key, Parse(depth + 1)));
                        Skip();
                        if (_i < _s.Length && _s[_i] == ',') { _i++; continue; }
                        if (_i < _s.Length && _s[_i] == '}') { _i++; return v; }
                        throw Fail("expected ',' or '}'");
                    }
                }
                if (c == '[')
                {
                    _i++;
                    v.Kind = Kind.Array;
                    v.Items = new List<Value>();
                    Skip();
                    if (_i < _s.Length && _s[_i] == ']') { _i++; return v; }
                    while (true)
                    {
                        v.Items.Add(Parse(depth + 1));
                        Skip();
                        if (_i < _s.Length && _s[_i] == ',') { _i++; continue; }
                        if (_i < _s.Length && _s[_i] == ']') { _i++; return v; }
                        throw Fail("expected ',' or ']'");
                    }
                }
                if (c == '"') { v.Kind = Kind.String; v.Text = ParseString(); return v; }
                if (Word("true")) { v.Kind = Kind.Boolean; v.Flag = true; return v; }
                if (Word("false")) { v.Kind = Kind.Boolean; return v; }
                if (Word("null")) { v.Kind = Kind.Null; return v; }
                int start = _i;
                while (_i < _s.Length && "+-0123456789.eE".IndexOf(_s[_i]) >= 0) _i++;
                if (_i == start || !double.TryParse(_s.Substring(start, _i - start), NumberStyles.Float, CultureInfo.InvariantCulture, out double n) || double.IsInfinity(n))
                    throw Fail("a value that is not a number, a string, true, false, null, a list or an object");
                v.Kind = Kind.Number;
                v.Number = n;
                return v;
            }

            bool Word(string w)
            {
                if (string.CompareOrdinal(_s, _i, w, 0, w.Length) != 0) return false;
                _i += w.Length;
                return true;
            }

            string ParseString()
            {
                var sb = new StringBuilder();
                _i++;
                while (true)
                {
                    if (_i >= _s.Length || _s[_i] == '\n') throw Fail("a string that does not end on its line");
                    char c = _s[_i++];
                    if (c == '"') return sb.ToString();
                    if (c != '\\') { sb.Append(c); continue; }
                    if (_i >= _s.Length) throw Fail("a string that does not end");
                    char e = _s[_i++];
                    switch (e)
                    {
                        case '"': case '\\': case '/': sb.Append(e); break;
                        case 'n': sb.Append('\n'); break;
                        case 't': sb.Append('\t'); break;
                        case 'r': sb.Append('\r'); break;
                        case 'b': sb.Append('\b'); break;
                        case 'f': sb.Append('\f'); break;
                        case 'u':
                            if (_i + 4 > _s.Length || !int.TryParse(_s.Substring(_i, 4), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out int code))
                                throw Fail("a bad \\u escape");
                            sb.Append((char)code);
                            _i += 4;
                            break;
                        default: throw Fail("a bad escape \\" + e);
                    }
                }
            }
        }
    }

    /// <summary>A profile file that cannot be read: the message starts "SOURCE:LINE: " and names the effect and the setting.</summary>
    public sealed class ProfileFormatException : FormatException
    {
        public string File { get; }
        public int Line { get; }

        public ProfileFormatException(string message, string source, int line) : base(message)
        {
            File = source;
            Line = line;
        }
    }
}
