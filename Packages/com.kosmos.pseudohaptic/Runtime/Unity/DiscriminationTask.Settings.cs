using System;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The task's procedure, plan and staircase as the inspector keeps them (the serialized fields, in
    /// DiscriminationTask.cs) and as <see cref="DiscriminationSettings"/>, both ways through one list of the fields
    /// (<see cref="Transfer"/>): a field added there is read and written alike.
    /// </summary>
    public sealed partial class DiscriminationTask
    {
        /// <summary>The inspector's plan and staircase settings (a new object each time).</summary>
        public DiscriminationSettings Settings
        {
            get
            {
                var settings = new DiscriminationSettings();
                Transfer(settings, TransferDirection.FieldsToSettings);
                return settings;
            }
        }

        /// <summary>Takes the procedure, plan and staircase of <paramref name="settings"/> (as the inspector would set them), for a
        /// task another component runs (the calibration's cue-strength staircase, <see cref="CueStrengthCalibrator"/>).</summary>
        public void Use(DiscriminationSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            Transfer(settings, TransferDirection.SettingsToFields);
        }

        /// <summary>Every setting with its serialized field, one line each, for both directions.</summary>
        void Transfer(DiscriminationSettings s, TransferDirection d)
        {
            FieldTransfer.Copy(d, ref s.Procedure, ref _procedure);
            FieldTransfer.Copy(d, ref s.StandardKg, ref _standardKg);
            FieldTransfer.Copy(d, ref s.ComparisonKg, ref _comparisonKg);
            FieldTransfer.Copy(d, ref s.Repetitions, ref _repetitions);
            FieldTransfer.Copy(d, ref s.CatchKg, ref _catchKg);
            FieldTransfer.Copy(d, ref s.CatchRepetitions, ref _catchRepetitions);
            FieldTransfer.Copy(d, ref s.Seed, ref _seed);
            FieldTransfer.Copy(d, ref s.StaircaseStartKg, ref _staircaseStartKg);
            FieldTransfer.Copy(d, ref s.StaircaseStepKg, ref _staircaseStepKg);
            FieldTransfer.Copy(d, ref s.HalvingReversals, ref _halvingReversals);
            FieldTransfer.Copy(d, ref s.MinStepKg, ref _minStepKg);
            FieldTransfer.Copy(d, ref s.StopAfterReversals, ref _stopAfterReversals);
            FieldTransfer.Copy(d, ref s.LastReversals, ref _lastReversals);
            FieldTransfer.Copy(d, ref s.MaxTrials, ref _maxTrials);
        }

        /// <summary>The plan these settings give at the study's seed.</summary>
        public ConstantStimuliPlan Plan() => Settings.Plan();

        /// <summary>The plan a participant runs in a condition: its order drawn from the study's seed and both names (the same for the same three).</summary>
        public ConstantStimuliPlan PlanFor(string participant, string condition) => Settings.PlanFor(participant, condition);

        /// <summary>The staircase these settings give for a participant and condition (the same for the same seed).</summary>
        public Staircase MakeStaircase(string participant, string condition) => Settings.MakeStaircase(participant, condition);
    }
}
