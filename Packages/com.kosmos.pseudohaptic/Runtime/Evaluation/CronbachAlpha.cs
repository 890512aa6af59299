using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Internal consistency of a multi-item part (Cronbach 1951):
    /// α = k/(k − 1) · (1 − Σᵢ s²ᵢ / s²ₜ), k items, s²ᵢ the variance of item i across participants and
    /// s²ₜ that of their item totals (both with divisor n − 1; the ratio does not depend on it). Computed
    /// on reverse-coded answers of participants who completed the part. NaN when undefined: fewer than two
    /// items or participants, or totals that do not vary.
    /// </summary>
    public sealed class CronbachAlpha
    {
        public double Alpha { get; }
        /// <summary>Participants whose answers went in (complete sheets only).</summary>
        public int Participants { get; }
        public int Items { get; }
        public bool IsDefined => !double.IsNaN(Alpha);

        CronbachAlpha(double alpha, int participants, int items)
        {
            Alpha = alpha;
            Participants = participants;
            Items = items;
        }

        /// <summary>α of a participants × items matrix; every row must have the same length.</summary>
        public static CronbachAlpha Compute(IReadOnlyList<IReadOnlyList<double>> rows)
        {
            if (rows == null) throw new ArgumentNullException(nameof(rows));
            int n = rows.Count;
            int k = n > 0 ? rows[0].Count : 0;
            for (int r = 0; r < n; r++)
                if (rows[r] == null || rows[r].Count != k) throw new ArgumentException("row " + r + " does not have " + k + " items", nameof(rows));
            if (n < 2 || k < 2) return new CronbachAlpha(double.NaN, n, k);

            double itemVariances = 0;
            for (int i = 0; i < k; i++)
            {
                double mean = 0;
                for (int r = 0; r < n; r++) mean += rows[r][i];
                mean /= n;
                double ss = 0;
                for (int r = 0; r < n; r++) ss += (rows[r][i] - mean) * (rows[r][i] - mean);
                itemVariances += ss / (n - 1);
            }

            var totals = new double[n];
            double totalMean = 0;
            for (int r = 0; r < n; r++)
            {
                for (int i = 0; i < k; i++) totals[r] += rows[r][i];
                totalMean += totals[r];
            }
            totalMean /= n;
            double totalSs = 0;
            for (int r = 0; r < n; r++) totalSs += (totals[r] - totalMean) * (totals[r] - totalMean);
            double totalVariance = totalSs / (n - 1);
            if (totalVariance <= 0) return new CronbachAlpha(double.NaN, n, k);

            double alpha = (double)k / (k - 1) * (1 - itemVariances / totalVariance);
            return new CronbachAlpha(alpha, n, k);
        }

        /// <summary>α of one questionnaire from the complete sheets among <paramref name="sheets"/> (reverse-coded answers).</summary>
        public static CronbachAlpha FromSheets(IEnumerable<AnswerSheet> sheets)
        {
            if (sheets == null) throw new ArgumentNullException(nameof(sheets));
            var rows = new List<IReadOnlyList<double>>();
            Questionnaire questionnaire = null;
            foreach (var sheet in sheets)
            {
                if (questionnaire == null) questionnaire = sheet.Questionnaire;
                else if (!ReferenceEquals(questionnaire, sheet.Questionnaire))
                    throw new ArgumentException("sheets of different questionnaires ('" + questionnaire.Id + "', '" + sheet.Questionnaire.Id + "')", nameof(sheets));
                if (!sheet.IsComplete) continue;
                var row = new double[questionnaire.ItemCount];
                for (int i = 0; i < row.Length; i++) row[i] = sheet.RecodedAt(i).Value;
                rows.Add(row);
            }
            if (rows.Count == 0) return new CronbachAlpha(double.NaN, 0, questionnaire != null ? questionnaire.ItemCount : 0);
            return Compute(rows);
        }

        /// <summary>α of the questionnaire <paramref name="questionnaireId"/> in a response set.</summary>
        public static CronbachAlpha Of(ResponseSet responses, string questionnaireId)
        {
            if (responses == null) throw new ArgumentNullException(nameof(responses));
            var sheets = responses.SheetsOf(questionnaireId);
            if (sheets.Count > 0) return FromSheets(sheets);
            var questionnaire = responses.Catalog.Find(questionnaireId);
            return new CronbachAlpha(double.NaN, 0, questionnaire != null ? questionnaire.ItemCount : 0);
        }
    }
}
