using System.Globalization;
using System.Text;

namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>
/// Every message the tool prints is one line: line breaks, tabs and other control characters (from a path or
/// from a file's content) are shown escaped (\n, \t, \x1B, \u0085), never sent to the terminal as they are.
/// </summary>
public static class Messages
{
    public static string OneLine(string? text)
    {
        if (string.IsNullOrEmpty(text)) return "";
        int i = 0;
        while (i < text.Length && !NeedsEscape(text[i])) i++;
        if (i == text.Length) return text;
        var sb = new StringBuilder(text.Length + 16).Append(text, 0, i);
        for (; i < text.Length; i++)
        {
            char c = text[i];
            if (!NeedsEscape(c)) { sb.Append(c); continue; }
            switch (c)
            {
                case '\n': sb.Append("\\n"); break;
                case '\r': sb.Append("\\r"); break;
                case '\t': sb.Append("\\t"); break;
                case '\0': sb.Append("\\0"); break;
                default:
                    if (c < 0x100) sb.Append("\\x").Append(((int)c).ToString("X2", CultureInfo.InvariantCulture));
                    else sb.Append("\\u").Append(((int)c).ToString("X4", CultureInfo.InvariantCulture));
                    break;
            }
        }
        return sb.ToString();
    }

    /// <summary>C0 and C1 controls, DEL, line and paragraph separators.</summary>
    static bool NeedsEscape(char c) => c < 0x20 || (c >= 0x7F && c <= 0x9F) || c == '\u2028' || c == '\u2029';

    /// <summary>An argument exception's message without the " (Parameter 'x')" .NET appends: the message says what is wrong.</summary>
    public static string WithoutParameter(ArgumentException e)
    {
        string? suffix = e.ParamName != null ? " (Parameter '" + e.ParamName + "')" : null;
        return suffix != null && e.Message.EndsWith(suffix, StringComparison.Ordinal) ? e.Message[..^suffix.Length] : e.Message;
    }

    /// <summary>A user's path as messages show it: "''" for the empty path, escaped controls otherwise.</summary>
    public static string Path(string path) => path.Length == 0 ? "''" : OneLine(path);

    /// <summary>The reason of an I/O failure, without the path .NET puts into it (which may be a temporary one).</summary>
    public static string Reason(Exception e) => e switch
    {
        UnauthorizedAccessException => "permission denied",
        FileNotFoundException or DirectoryNotFoundException => "does not exist",
        PathTooLongException => "the name is too long",
        _ => StripPaths(e.Message),
    };

    static string StripPaths(string message)
    {
        // .NET writes "... : '/full/path'" or "'path' ..."; keep the words, drop what is quoted.
        var sb = new StringBuilder();
        bool quoted = false;
        foreach (char c in message)
        {
            if (c == '\'') { quoted = !quoted; continue; }
            if (!quoted) sb.Append(c);
        }
        string s = sb.ToString().Replace(" : ", " ").Replace("  ", " ").Trim().TrimEnd('.', ':', ' ');
        return s.Length == 0 ? "input/output error" : OneLine(s);
    }
}
