using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// A figure of the accuracy study: the mean over its seeded renders and the 95 % confidence interval of that mean
/// (Student's t, n − 1 degrees of freedom). A verdict against a target is given only where the interval clears it.
/// </summary>
public readonly record struct Interval(double Mean, double Low, double High, int N)
{
    public const double Confidence = 0.95;

    public static Interval Of(IEnumerable<double> values)
    {
        var v = values.Where(double.IsFinite).ToList();
        if (v.Count == 0) return new Interval(double.NaN, double.NaN, double.NaN, 0);
        double mean = v.Average();
        if (v.Count == 1) return new Interval(mean, double.NaN, double.NaN, 1);
        double sd = Math.Sqrt(v.Sum(x => (x - mean) * (x - mean)) / (v.Count - 1));
        double half = StudentT.TwoSidedCritical(Confidence, v.Count - 1) * sd / Math.Sqrt(v.Count);
        return new Interval(mean, mean - half, mean + half, v.Count);
    }

    public double HalfWidth => (High - Low) / 2;

    /// <summary>"met" where the whole interval lies at or under <paramref name="target"/>, "missed" where it lies above,
    /// otherwise undecided: the interval holds the target.</summary>
    public string Verdict(double target) =>
        !(N > 1) ? "not measured"
        : High <= target ? "met"
        : Low > target ? "missed"
        : "undecided (the interval holds the target)";
}
