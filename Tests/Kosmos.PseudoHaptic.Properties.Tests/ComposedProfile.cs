using System.Globalization;
using FsCheck;
using FsCheck.Fluent;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>One effect of a composed profile: its registered name and a value for each of its settings (the descriptor's order).</summary>
public sealed record EffectChoice(string Name, double[] Values)
{
    public EffectDescriptor Descriptor => EffectRegistry.Get(Name);

    public WeightEffect Build()
    {
        var s = Descriptor.DefaultSettings();
        for (int i = 0; i < Values.Length; i++) s[i] = Values[i];
        return s.Build();
    }

    public override string ToString()
    {
        var d = Descriptor;
        return Values.Length == 0 ? Name : Name + "(" + string.Join(", ", Values.Select((v, i) => d.Settings[i].Name + " " + d.Settings[i].Format(v))) + ")";
    }
}

/// <summary>Which solver runs a composed profile: the y solver, or <see cref="WeightSolver3D"/> with one hand or (where the
/// profile has <see cref="TwoHands"/>) two.</summary>
public enum SolverKind { Y, OneHand, TwoHands }

/// <summary>
/// A profile as a researcher composes one in a profile file (<see cref="ProfileJson"/>): any subset of the package's
/// effects (<see cref="EffectRegistry.Package"/>), in any order (the profile runs them by stage, in the given order within
/// a stage), each setting anywhere in its declared range, with extra weight on the range's ends, on zero and on the
/// default; the safety limits at their defaults or drawn in their ranges alike; sometimes the one hand filter a file can
/// name; and the object and user it runs for: a mass from 1 g to 1 t (1 g, 10 g, the standard 45 g and 1 t often), a
/// standard speed in [0.05, 5] m/s, and the solver (y, 3D one hand, 3D two hands where the profile has two-hands).
/// </summary>
public sealed class ComposedProfile
{
    public EffectChoice[] Effects = Array.Empty<EffectChoice>();
    /// <summary>The limits' values in <see cref="SolverLimits.Settings"/>' order; null: the defaults.</summary>
    public double[] Limits;
    public bool OneSecondAverage;
    public double MassKg = PhysicalConstants.StandardMassKg, StandardSpeed = WeightSolver.DefaultStandardSpeed;
    public SolverKind Solver;

    public SolverLimits BuildLimits() => Limits == null ? SolverLimits.Default : new SolverLimits(Limits[0], Limits[1], Limits[2], Limits[3], Limits[4]);

    /// <summary>The profile. Every value lies in its declared range, so building it never throws (a profile refuses only an
    /// effect listed twice, which the generator never draws); what a solver refuses, it refuses when it is constructed.</summary>
    public WeightProfile Build(string name = "composed")
        => new WeightProfile(name, Effects.Select(e => e.Build()).ToArray(), BuildLimits(), OneSecondAverage ? new OneSecondAverage() : null);

    public bool Has(string effect) => Effects.Any(e => e.Name == effect);

    public double Setting(string effect, string setting)
    {
        var e = Effects.First(x => x.Name == effect);
        return e.Values[e.Descriptor.Settings.ToList().FindIndex(s => s.Name == setting)];
    }

    /// <summary>Whether <see cref="WeightSolver3D"/> refuses the profile when it is configured (ALGORITHM.md §6, "Break-away"):
    /// break-away under the offset correction with neither the speed cap nor the lateral inertia ("could never fire"), or a
    /// break-away distance beyond (1 + maxGain) × workspaceRadius ("could never be reached"). The y solver refuses nothing.</summary>
    public bool RefusedIn3D()
    {
        if (!Has("break-away")) return false;
        if (Has("offset-correction") && !Has("speed-cap") && !Has("lateral-inertia")) return true;
        var l = BuildLimits();
        return Setting("break-away", "distance") > (1 + l.MaxGain) * l.WorkspaceRadius;
    }

    public override string ToString()
    {
        string limits = Limits == null ? "default limits" : "limits(" + string.Join(", ", Limits.Select((v, i) => SolverLimits.Settings[i].Name + " " + SolverLimits.Settings[i].Format(v))) + ")";
        return $"{Solver}, {MassKg.ToString("R", CultureInfo.InvariantCulture)} kg, v_std {StandardSpeed.ToString("R", CultureInfo.InvariantCulture)}, [{string.Join(", ", Effects.Select(e => e.ToString()))}], {limits}{(OneSecondAverage ? ", one-second-average" : "")}";
    }

    internal ComposedProfile With(Action<ComposedProfile> change)
    {
        var c = (ComposedProfile)MemberwiseClone();
        c.Effects = Effects.Select(e => e with { Values = (double[])e.Values.Clone() }).ToArray();
        c.Limits = (double[])Limits?.Clone();
        change(c);
        return c;
    }

    // ---- generation --------------------------------------------------------------------------------------------------------

    static Gen<double> Unit() => Gen.Choose(0, 1 << 30).Select(v => v / (double)(1 << 30));

    static Gen<double> Uniform(double lo, double hi) => Unit().Select(u => Math.Min(hi, Math.Max(lo, lo + (hi - lo) * u)));

    static Gen<double> LogUniform(double lo, double hi) => Unit().Select(u => Math.Min(hi, Math.Max(lo, lo * Math.Pow(hi / lo, u))));

    /// <summary>A value of <paramref name="s"/> in its declared range: its ends (for a range open above, the largest
    /// double and 1e12; for one open at 0, the smallest positive double and 1e-12), zero where it is allowed, the default,
    /// near the default, uniform over the range, and log-uniform over it (so that a range of 0.01–1000 is not almost always
    /// hundreds).</summary>
    public static Gen<double> Value(SettingDescriptor s)
    {
        if (s.Kind == SettingKind.Boolean) return Gen.Elements(0.0, 1.0);
        var choices = new List<(int, Gen<double>)> { (2, Gen.Constant(s.Default)) };
        if (s.MinExclusive && double.IsPositiveInfinity(s.Max))
        {
            choices.Add((3, Gen.Elements(double.Epsilon, 1e-12, 1e12, double.MaxValue)));
            choices.Add((4, LogUniform(1e-4, 1e4)));
            choices.Add((3, LogUniform(s.Default / 10, s.Default * 10)));
        }
        else if (double.IsPositiveInfinity(s.Max))
        {
            // A least value and no greatest (glideSpeed): the least, the largest finite, and log-uniform above the least.
            choices.Add((3, Gen.Constant(s.Min)));
            choices.Add((2, Gen.Constant(double.MaxValue)));
            choices.Add((4, LogUniform(s.Min, s.Min * 1e6)));
            choices.Add((3, LogUniform(s.Default / 10, s.Default * 10)));
        }
        else
        {
            double lo = s.MinExclusive ? Math.BitIncrement(s.Min) : s.Min, hi = s.Max;
            choices.Add((3, Gen.Constant(lo)));
            choices.Add((3, Gen.Constant(hi)));
            if (lo <= 0 && 0 <= hi) choices.Add((2, Gen.Constant(0.0)));
            double d = Math.Max(Math.Abs(s.Default), 1);
            choices.Add((3, Uniform(Math.Max(lo, s.Default - d), Math.Min(hi, s.Default + d))));
            choices.Add((3, Uniform(lo, hi)));
            if (lo > 0) choices.Add((3, LogUniform(lo, hi)));
            else if (hi > 0) choices.Add((3, LogUniform(Math.Max(hi * 1e-6, 1e-9), hi)));
        }
        return Gen.Frequency(choices.ToArray());
    }

    static Gen<EffectChoice> Choice(EffectDescriptor d) => Gen.CollectToArray(d.Settings, Value).Select(v => new EffectChoice(d.Name, v));

    /// <summary>1 g to 1 t: 1 g, 10 g, the standard 45 g and 1 t often, a few masses between, and log-uniform over the range.</summary>
    public static Gen<double> Mass() => Gen.Frequency(
        (3, Gen.Elements(0.001, 0.01, PhysicalConstants.StandardMassKg, 1000.0)),
        (2, Gen.Elements(0.1, 0.5, 1.0, 2.0, 5.0, 100.0)),
        (3, LogUniform(0.001, 1000)));

    static Gen<double> StandardSpeed_() => Gen.Frequency(
        (3, Gen.Constant(WeightSolver.DefaultStandardSpeed)),
        (1, Gen.Elements(WeightSolver.MinStandardSpeed, WeightSolver.MaxStandardSpeed)),
        (2, LogUniform(WeightSolver.MinStandardSpeed, WeightSolver.MaxStandardSpeed)));

    static Gen<double[]> LimitValues() => Gen.Frequency(
        (1, Gen.Constant<double[]>(null)),
        (1, Gen.CollectToArray(SolverLimits.Settings, s => Gen.Frequency((1, Gen.Constant(s.Default)), (1, Value(s))))));

    /// <summary>Composed profiles over <paramref name="effects"/> (the package's by default); <paramref name="limits"/> draws the
    /// safety limits (else they are the defaults).</summary>
    public static Gen<ComposedProfile> Generator(bool limits = true, IReadOnlyList<EffectDescriptor> effects = null)
    {
        effects ??= EffectRegistry.Package;
        return from subset in Gen.SubListOf(effects.ToArray())
               from order in Gen.Shuffle(subset.ToArray())
               from choices in Gen.CollectToArray(order, Choice)
               from limitValues in limits ? LimitValues() : Gen.Constant<double[]>(null)
               from filter in Gen.Frequency((7, Gen.Constant(false)), (1, Gen.Constant(true)))
               from mass in Mass()
               from speed in StandardSpeed_()
               from solver in Gen.Elements(SolverKind.Y, SolverKind.OneHand, SolverKind.TwoHands)
               select new ComposedProfile
               {
                   Effects = choices, Limits = limitValues, OneSecondAverage = filter, MassKg = mass, StandardSpeed = speed,
                   Solver = solver == SolverKind.TwoHands && !choices.Any(c => c.Name == "two-hands") ? SolverKind.OneHand : solver,
               };
    }

    static readonly double[] RoundMasses = { 1.0, PhysicalConstants.StandardMassKg, 0.001, 1000 };

    /// <summary>Simpler profiles: an effect fewer, a setting at its default, the default limits (then one limit at its
    /// default), no hand filter, the y solver, one hand, a round mass, the default standard speed.</summary>
    public static IEnumerable<ComposedProfile> Shrink(ComposedProfile p)
    {
        for (int i = 0; i < p.Effects.Length; i++)
        {
            int skip = i;
            yield return p.With(x =>
            {
                x.Effects = p.Effects.Where((_, j) => j != skip).Select(e => e with { Values = (double[])e.Values.Clone() }).ToArray();
                if (x.Solver == SolverKind.TwoHands && !x.Has("two-hands")) x.Solver = SolverKind.OneHand;
            });
        }
        if (p.Limits != null)
        {
            yield return p.With(x => x.Limits = null);
            for (int i = 0; i < p.Limits.Length; i++)
                if (p.Limits[i] != SolverLimits.Settings[i].Default) { int at = i; yield return p.With(x => x.Limits[at] = SolverLimits.Settings[at].Default); }
        }
        if (p.OneSecondAverage) yield return p.With(x => x.OneSecondAverage = false);
        if (p.Solver != SolverKind.Y) yield return p.With(x => x.Solver = SolverKind.Y);
        if (p.Solver == SolverKind.TwoHands) yield return p.With(x => x.Solver = SolverKind.OneHand);
        for (int i = 0; i < p.Effects.Length; i++)
            for (int k = 0; k < p.Effects[i].Values.Length; k++)
            {
                double def = p.Effects[i].Descriptor.Settings[k].Default;
                if (p.Effects[i].Values[k] != def) { int a = i, b = k; yield return p.With(x => x.Effects[a].Values[b] = def); }
            }
        // Toward 1 kg, then the standard weight, 1 g, 1 t: only to a mass earlier in that list (a shrink never cycles).
        int rank = Array.IndexOf(RoundMasses, p.MassKg);
        for (int i = 0; i < (rank < 0 ? RoundMasses.Length : rank); i++) { double m = RoundMasses[i]; yield return p.With(x => x.MassKg = m); }
        if (p.StandardSpeed != WeightSolver.DefaultStandardSpeed) yield return p.With(x => x.StandardSpeed = WeightSolver.DefaultStandardSpeed);
    }
}
