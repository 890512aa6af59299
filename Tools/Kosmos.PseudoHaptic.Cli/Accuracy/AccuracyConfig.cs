using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// One row of the study: how it moves the object from frames (<see cref="Run"/>), and the reference profile it
/// is judged against (run by the solver on the noise-free 1 kHz hand).
/// </summary>
public sealed record AccuracyConfig(
    string Key,
    string Group,
    string Description,
    Func<IReadOnlyList<TraceFrame>, double[]> Run,
    WeightProfile Reference)
{
    public const string EstimatorGroup = "estimator";
    public const string IntegrationGroup = "integration";

    /// <summary>
    /// The study's rows for one object and user. Estimators: the paper profile with each estimator, against
    /// the paper profile without deadband or filter. Integration and precision: gain only (the paper profile's
    /// G, no effects), against the solver with the same gain-only profile.
    /// </summary>
    public static List<AccuracyConfig> All(WeightModel model, double standardSpeed)
    {
        var list = new List<AccuracyConfig>();
        var reference = EstimatorCatalog.ReferenceProfile();
        foreach (var key in EstimatorCatalog.EstimatorKeys)
        {
            var profile = EstimatorCatalog.EstimatorProfile(key);
            list.Add(new AccuracyConfig(key, EstimatorGroup, EstimatorCatalog.Describe(key),
                frames => TraceReplay.Run(new WeightSolver(model, profile, standardSpeed), frames), reference));
        }

        var gainOnly = EstimatorCatalog.GainOnly;
        double gain = new WeightSolver(model, gainOnly, standardSpeed).Gain;
        list.Add(new AccuracyConfig("increments", IntegrationGroup, "the solver: object += G·Δpose per new pose, double state",
            frames => TraceReplay.Run(new WeightSolver(model, gainOnly, standardSpeed), frames), gainOnly));
        list.Add(new AccuracyConfig("increments-float", IntegrationGroup, "the same increments with float state (harness)",
            frames => IntegratorReplay.Run(new IncrementIntegrator<float>(gain), frames), gainOnly));
        list.Add(new AccuracyConfig("velocity-dt", IntegrationGroup, "object += G·v_hand·dt per frame (harness)",
            frames => IntegratorReplay.Run(new VelocityIntegrator(gain), frames), gainOnly));
        list.Add(new AccuracyConfig("velocity-substep4", IntegrationGroup, "G·v_hand integrated in 4 sub-steps per frame, v ramped (harness)",
            frames => IntegratorReplay.Run(new VelocityIntegrator(gain, 4), frames), gainOnly));
        list.Add(new AccuracyConfig(EstimatorCatalog.PaperLiteral, IntegrationGroup, EstimatorCatalog.Describe(EstimatorCatalog.PaperLiteral),
            frames => IntegratorReplay.Run(new IntegratorReplay.PaperLiteral(model.MassKg), frames), gainOnly));
        return list;
    }
}
