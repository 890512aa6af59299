namespace Kosmos.PseudoHaptic.UnityCompile;

/// <summary>
/// An asmdef versionDefine's expression, as Unity 2022.3 reads it (manual: "Define symbols based on Unity and project
/// package versions"; UnityCsReference Editor/Mono/Scripting/ScriptCompilation/ExpressionTypeFactory.cs): <c>1.2.3</c>
/// is x ≥ 1.2.3, <c>[1.2.3]</c> x = 1.2.3, <c>(1.2,)</c> x &gt; 1.2, <c>(,2.0]</c> x ≤ 2.0, <c>(,2.0)</c> x &lt; 2.0, and
/// <c>[a,b]</c>, <c>(a,b)</c>, <c>[a,b)</c>, <c>(a,b]</c> the ranges. Any other form is invalid (Unity logs it and
/// defines nothing): <see cref="FormatException"/>. Versions compare as numbers part by part; a package pre-release
/// (1.5.0-pre.4) comes before its release, and a Unity version's letter (a &lt; b &lt; f &lt; p) before its number.
/// </summary>
public static class VersionExpression
{
    public static bool Matches(string expression, string version)
    {
        expression = expression.Trim();
        if (expression.Length == 0) throw new FormatException("an empty expression");
        char first = expression[0], last = expression[^1];
        bool bracketed = first is '[' or '(';
        if (bracketed != (last is ']' or ')')) throw new FormatException("'" + expression + "': missing symbol in start or end");
        if (!bracketed) return Compare(version, expression) >= 0;
        string inner = expression[1..^1];
        int comma = inner.IndexOf(',');
        if (comma < 0)
        {
            if (first == '[' && last == ']') return Compare(version, inner) == 0;
            throw new FormatException("'" + expression + "' is not a valid expression");
        }
        string left = inner[..comma].Trim(), right = inner[(comma + 1)..].Trim();
        bool lo = left.Length > 0, hi = right.Length > 0;
        if (lo && !hi && first == '(' && last == ')') return Compare(version, left) > 0;
        if (!lo && hi && first == '(' && last == ']') return Compare(version, right) <= 0;
        if (!lo && hi && first == '(' && last == ')') return Compare(version, right) < 0;
        if (lo && hi)
        {
            bool aboveLeft = first == '[' ? Compare(version, left) >= 0 : Compare(version, left) > 0;
            bool belowRight = last == ']' ? Compare(version, right) <= 0 : Compare(version, right) < 0;
            return aboveLeft && belowRight;
        }
        throw new FormatException("'" + expression + "' is not a valid expression");
    }

    /// <summary>Part by part: numbers as numbers; a pre-release tag or a Unity release letter ranks below a plain number.</summary>
    public static int Compare(string a, string b)
    {
        long[] x = Parse(a), y = Parse(b);
        for (int i = 0; i < Math.Max(x.Length, y.Length); i++)
        {
            long p = i < x.Length ? x[i] : 0, q = i < y.Length ? y[i] : 0;
            if (p != q) return p.CompareTo(q);
        }
        return 0;
    }

    /// <summary>"2022.3.50f1" → 2022, 3, 50, (f), 1; "1.5.0-pre.4" → 1, 5, 0, (pre), 4; "68.0.2" → 68, 0, 2, (release).</summary>
    static long[] Parse(string v)
    {
        var parts = new List<long>();
        var m = System.Text.RegularExpressions.Regex.Match(v.Trim(), @"^(\d+)(?:\.(\d+))?(?:\.(\d+))?(?:([a-z]+|-[0-9A-Za-z.-]+)(\d*))?$");
        if (!m.Success) throw new FormatException("'" + v + "' is not a version");
        for (int g = 1; g <= 3; g++) parts.Add(m.Groups[g].Success ? long.Parse(m.Groups[g].Value) : 0);
        string tag = m.Groups[4].Value;
        // Unity letters: a(lpha) < b(eta) < f(inal) < p(atch); a package's "-pre.N" sorts before its release.
        long rank = tag.Length == 0 ? 100 : tag.StartsWith('-') ? 0 : tag switch { "a" => 10, "b" => 20, "f" => 30, "p" => 40, _ => 5 };
        parts.Add(rank);
        string tail = tag.StartsWith('-') ? new string(tag.Where(char.IsDigit).ToArray()) : m.Groups[5].Value;
        parts.Add(tail.Length > 0 ? long.Parse(tail) : 0);
        return parts.ToArray();
    }
}
