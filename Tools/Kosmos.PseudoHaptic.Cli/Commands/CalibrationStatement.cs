namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// The calibration told as it is (issue 31): how far the user's standard speed moves the reference lift
/// (<see cref="ReferenceLift"/>: 0.2 m in 0.6 s) of the chosen mass under the chosen profile, against the ends of the
/// range people lift at (v_std 0.25 and 1.0 m/s), all computed by the solver.
/// </summary>
public static class CalibrationStatement
{
    public const double SlowUser = 0.25, FastUser = 1.0;

    public static string Line(WeightProfile profile, double massKg, double standardSpeed, double cueStrength)
    {
        double at = ReferenceLift.EndLag(profile, massKg, standardSpeed, cueStrength);
        double slow = ReferenceLift.EndLag(profile, massKg, SlowUser, cueStrength);
        double fast = ReferenceLift.EndLag(profile, massKg, FastUser, cueStrength);
        string Mm(double lag) => NumberText.Fixed(Math.Abs(lag) * 1000, 1) + " mm";
        string Side(double lag) => lag >= 0 ? "behind" : "ahead";
        return $"v_std {standardSpeed.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture)} m/s: a {NumberText.Format(ReferenceLift.Rise)} m lift of {NumberText.Format(massKg)} kg in {NumberText.Format(ReferenceLift.DefaultSeconds)} s ends {Mm(at)} {Side(at)} under {Files.Messages.OneLine(profile.Name)}"
               + (cueStrength != 1 ? $" at cue strength {NumberText.Fixed(cueStrength, 3)}" : "")
               + $"; at {NumberText.Format(SlowUser)} or {NumberText.Format(FastUser)} m/s {Mm(slow)} or {Mm(fast)} {Side(fast)}"
               + $" (the standard speed moves it {NumberText.Fixed(Math.Abs(fast - slow) * 1000, 1)} mm over that range)";
    }
}
