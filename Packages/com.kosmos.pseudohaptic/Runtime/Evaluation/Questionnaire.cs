using System;
using System.Collections.Generic;
using System.Globalization;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One part of the paper's evaluation (section 5, Appendices A and B): an id used in the CSV files, a
    /// title, an integer answer scale [ScaleMin, ScaleMax] and numbered items, some reverse-coded.
    /// Immutable; an inconsistent definition throws here. The definitions themselves are data:
    /// Runtime/Evaluation/Questionnaires/*.json, read by <see cref="QuestionnaireJson"/>.
    /// </summary>
    public sealed class Questionnaire
    {
        readonly QuestionnaireItem[] items;
        readonly Dictionary<int, QuestionnaireItem> byNumber;

        public string Id { get; }
        public string Title { get; }
        /// <summary>Shown before the first item; may be empty.</summary>
        public string Instructions { get; }
        public int ScaleMin { get; }
        public int ScaleMax { get; }
        /// <summary>Words for the scale's ends ("Strongly disagree"); may be empty.</summary>
        public string ScaleMinLabel { get; }
        public string ScaleMaxLabel { get; }
        /// <summary>In definition order.</summary>
        public IReadOnlyList<QuestionnaireItem> Items => items;
        public int ItemCount => items.Length;

        public Questionnaire(string id, string title, int scaleMin, int scaleMax, IEnumerable<QuestionnaireItem> items,
            string instructions = "", string scaleMinLabel = "", string scaleMaxLabel = "")
        {
            if (string.IsNullOrWhiteSpace(id)) throw new ArgumentException("questionnaire id is empty", nameof(id));
            if (id.Trim() != id || id.IndexOf(',') >= 0 || id.IndexOf('"') >= 0)
                throw new ArgumentException("questionnaire id '" + id + "' has surrounding spaces, a comma or a quote", nameof(id));
            if (scaleMin >= scaleMax)
                throw new ArgumentException("questionnaire '" + id + "': scale min " + scaleMin + " is not below max " + scaleMax);
            if (items == null) throw new ArgumentNullException(nameof(items));

            var list = new List<QuestionnaireItem>(items);
            if (list.Count == 0) throw new ArgumentException("questionnaire '" + id + "' has no items", nameof(items));
            byNumber = new Dictionary<int, QuestionnaireItem>(list.Count);
            foreach (var item in list)
            {
                if (item == null) throw new ArgumentException("questionnaire '" + id + "' has a null item", nameof(items));
                if (item.Number < 1)
                    throw new ArgumentException("questionnaire '" + id + "': item number " + item.Number + " is below 1");
                if (byNumber.ContainsKey(item.Number))
                    throw new ArgumentException("questionnaire '" + id + "': item number " + item.Number + " appears twice");
                byNumber.Add(item.Number, item);
            }

            Id = id;
            Title = string.IsNullOrEmpty(title) ? id : title;
            Instructions = instructions ?? "";
            ScaleMin = scaleMin;
            ScaleMax = scaleMax;
            ScaleMinLabel = scaleMinLabel ?? "";
            ScaleMaxLabel = scaleMaxLabel ?? "";
            this.items = list.ToArray();
        }

        /// <summary>The item with this number, or null.</summary>
        public QuestionnaireItem FindItem(int number)
        {
            QuestionnaireItem item;
            return byNumber.TryGetValue(number, out item) ? item : null;
        }

        public bool IsOnScale(int response) => response >= ScaleMin && response <= ScaleMax;

        /// <summary>
        /// Why an answer to item <paramref name="number"/> cannot be accepted (unknown item, not a finite whole
        /// number, off the scale), or null when it can. The one check that the CSV reader and
        /// <see cref="ResponseSet"/> share; takes a double so that "3.5" and "1e20" are refused in words.
        /// </summary>
        public string Reject(int number, double response)
        {
            string n = number.ToString(CultureInfo.InvariantCulture);
            if (FindItem(number) == null)
                return "questionnaire '" + Id + "' has no item " + n + " (items are " + ItemRange() + ")";
            if (double.IsNaN(response) || double.IsInfinity(response))
                return "response to '" + Id + "' item " + n + " is not a number";
            string r = response.ToString("R", CultureInfo.InvariantCulture);
            if (response < ScaleMin || response > ScaleMax)
                return "response " + r + " to '" + Id + "' item " + n + " is outside the scale " + ScaleText();
            if (Math.Floor(response) != response)
                return "response " + r + " to '" + Id + "' item " + n + " is not a whole number on the scale " + ScaleText();
            return null;
        }

        /// <summary>"1 to 5".</summary>
        public string ScaleText() => ScaleMin.ToString(CultureInfo.InvariantCulture) + " to " + ScaleMax.ToString(CultureInfo.InvariantCulture);

        /// <summary>
        /// The answer as it counts towards the score: a reverse-coded item is mirrored on the scale,
        /// min + max − x (6 − x on the paper's 5-point scale); others count as given.
        /// </summary>
        public int Recode(int number, int response)
        {
            string why = Reject(number, response);
            if (why != null) throw new ArgumentOutOfRangeException(nameof(response), why);
            return byNumber[number].Reverse ? ScaleMin + ScaleMax - response : response;
        }

        /// <summary>"1 to 10" when the numbers run without a gap from 1, else "1, 2, 5".</summary>
        string ItemRange()
        {
            var numbers = new List<int>(items.Length);
            foreach (var item in items) numbers.Add(item.Number);
            numbers.Sort();
            if (numbers[0] == 1 && numbers[numbers.Count - 1] == numbers.Count)
                return numbers.Count == 1 ? "1" : "1 to " + numbers.Count.ToString(CultureInfo.InvariantCulture);
            var text = new List<string>(numbers.Count);
            foreach (int number in numbers) text.Add(number.ToString(CultureInfo.InvariantCulture));
            return string.Join(", ", text);
        }

        public override string ToString() => Id;
    }
}
