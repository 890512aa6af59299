namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>
/// A generated block in a document: the lines from <c>&lt;!-- generated: NAME …--&gt;</c> to <c>&lt;!-- end generated: NAME
/// --&gt;</c>, each marker starting a line. The effects table (<c>profiles --markdown</c>) and the personalization tables
/// (ALGORITHM.md §12, evaluation.md §9) are kept so; their tests require exactly one pair of markers per block.
/// </summary>
public static class GeneratedBlock
{
    /// <summary>The start of the first line of block <paramref name="name"/> (what follows is " -->" or " (…) -->").</summary>
    public static string StartMarker(string name) => "<!-- generated: " + name + " ";

    /// <summary>The last line of block <paramref name="name"/>.</summary>
    public static string EndMarker(string name) => "<!-- end generated: " + name + " -->";

    /// <summary>
    /// <paramref name="existing"/> with <paramref name="block"/> in place of block <paramref name="name"/>, the text before and
    /// after kept. Null when it holds not exactly one start marker followed by one end marker, each starting a line.
    /// </summary>
    public static string? Replace(string existing, string name, string block)
    {
        string startMarker = StartMarker(name), endMarker = EndMarker(name);
        int start = LineStarting(existing, startMarker, 0);
        if (start < 0 || LineStarting(existing, startMarker, start + 1) >= 0) return null;
        int end = LineStarting(existing, endMarker, start);
        if (end < 0 || LineStarting(existing, endMarker, end + 1) >= 0) return null;
        int after = existing.IndexOf('\n', end);
        return existing.Substring(0, start) + block + (after < 0 ? "" : existing.Substring(after + 1));
    }

    /// <summary>Where the first line from <paramref name="from"/> on that starts with <paramref name="text"/> begins, or −1.</summary>
    static int LineStarting(string s, string text, int from)
    {
        for (int i = s.IndexOf(text, from, StringComparison.Ordinal); i >= 0; i = s.IndexOf(text, i + 1, StringComparison.Ordinal))
            if (i == 0 || s[i - 1] == '\n') return i;
        return -1;
    }
}
