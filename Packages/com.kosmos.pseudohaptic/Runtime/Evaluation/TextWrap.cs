using System;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Breaks text into lines of at most a given number of characters, for text that does not wrap itself
    /// (a 3D text mesh in the headset). Breaks at spaces; a word longer than a line is cut; existing line
    /// breaks are kept; runs of spaces at a break are dropped.
    /// </summary>
    public static class TextWrap
    {
        /// <summary>The text with '\n' inserted so that no line is longer than <paramref name="maxChars"/>.</summary>
        public static string Wrap(string text, int maxChars)
        {
            if (maxChars < 1) throw new ArgumentOutOfRangeException(nameof(maxChars), "a line holds at least one character");
            if (string.IsNullOrEmpty(text)) return "";
            var output = new StringBuilder(text.Length + 8);
            string[] paragraphs = text.Replace("\r\n", "\n").Split('\n');
            for (int p = 0; p < paragraphs.Length; p++)
            {
                if (p > 0) output.Append('\n');
                WrapParagraph(paragraphs[p], maxChars, output);
            }
            return output.ToString();
        }

        static void WrapParagraph(string paragraph, int maxChars, StringBuilder output)
        {
            string[] words = paragraph.Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries);
            int lineLength = 0;
            foreach (string whole in words)
            {
                string word = whole;
                if (lineLength > 0 && lineLength + 1 + word.Length <= maxChars)
                {
                    output.Append(' ').Append(word);
                    lineLength += 1 + word.Length;
                    continue;
                }
                if (lineLength > 0) output.Append('\n');
                while (word.Length > maxChars)
                {
                    output.Append(word, 0, maxChars).Append('\n');
                    word = word.Substring(maxChars);
                }
                output.Append(word);
                lineLength = word.Length;
            }
        }
    }
}
