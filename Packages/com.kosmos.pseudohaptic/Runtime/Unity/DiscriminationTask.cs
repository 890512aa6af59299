using Kosmos.PseudoHaptic.Evaluation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The in-headset weight discrimination task (two-alternative forced choice, issue 11): two objects of the
    /// same look stand left and right; each trial gives them the masses of the plan's standard and comparison
    /// (never shown; from a constant-stimuli plan or a transformed staircase), the participant lifts both and
    /// pokes the button on the side of the one that felt heavier. A catch trial is answered like any other. All of the logic is engine-free: the
    /// <see cref="DiscriminationSession"/> (plan from its seed, lift-then-answer, the trials file written by
    /// write-then-rename after every answer, resume), its <see cref="DiscriminationSettings"/> and the
    /// <see cref="DiscriminationTaskModel"/> (begin, sides, debounce, errors, the text shown): this component only
    /// applies the masses, forwards lifts and pokes, puts the objects back between trials, and shows the text.
    /// </summary>
    /// <remarks>
    /// The two objects must take their mass from <c>Explicit Mass Kg</c> (Mass = Explicit); the task sets it
    /// for every trial. The trials file is read by <c>pseudohaptic psychometric</c>. The inspector's settings both
    /// ways: DiscriminationTask.Settings.cs; the two objects: DiscriminationTask.Objects.cs.
    /// </remarks>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Discrimination Task")]
    public sealed partial class DiscriminationTask : MonoBehaviour
    {
        [Header("Participant and file")]
        [Tooltip("The participant's id as the trials file names it.")]
        [SerializeField] string _participant = "";
        [Tooltip("The study condition of this session (e.g. 'with effect', 'without'); may be empty.")]
        [SerializeField] string _condition = "";
        [Tooltip("Begin (or resume) at Start when a participant is set; otherwise call Begin from code.")]
        [SerializeField] bool _beginOnStart = true;
        [Tooltip("The trials file; a relative path is taken under Kosmos.PseudoHaptic in Application.persistentDataPath.")]
        [SerializeField] string _trialsFile = DiscriminationTaskModel.DefaultTrialsFile;
        [Tooltip("Constant stimuli (the levels below) or a transformed staircase (the staircase settings below).")]
        [SerializeField] DiscriminationProcedure _procedure = DiscriminationProcedure.ConstantStimuli;
        [Header("Plan (method of constant stimuli)")]
        [Tooltip("The standard's mass, kg.")]
        [SerializeField] float _standardKg = 0.5f;
        [Tooltip("The comparison masses, kg (Samad et al. 2019 used 0.7 … 1.3 × the standard in 7 steps).")]
        [SerializeField] float[] _comparisonKg = { 0.35f, 0.4f, 0.45f, 0.5f, 0.55f, 0.6f, 0.65f };
        [Tooltip("Repetitions of each comparison.")]
        [SerializeField] int _repetitions = 12;
        [Tooltip("Catch comparisons, kg: differences no attentive participant misses (e.g. 0.5× and 2× the standard).")]
        [SerializeField] float[] _catchKg = new float[0];
        [Tooltip("Repetitions of each catch comparison.")]
        [SerializeField] int _catchRepetitions = 0;
        [Tooltip("The study's seed: each participant and condition runs in its own order drawn from it and their names; the same three give the same order, so a session can resume.")]
        [SerializeField] int _seed = 1;
        [Header("Staircase")]
        [Tooltip("The comparison's first mass, kg.")]
        [SerializeField] float _staircaseStartKg = 0.7f;
        [Tooltip("The first step, kg; it halves at each of the first Halving Reversals reversals.")]
        [SerializeField] float _staircaseStepKg = 0.08f;
        [SerializeField] int _halvingReversals = 2;
        [Tooltip("Smallest step, kg.")]
        [SerializeField] float _minStepKg = 0.01f;
        [Tooltip("The run stops after this many reversals.")]
        [SerializeField] int _stopAfterReversals = 12;
        [Tooltip("The threshold is the mean of the levels at the last this many reversals.")]
        [SerializeField] int _lastReversals = 8;
        [Tooltip("The run stops after this many trials in any case.")]
        [SerializeField] int _maxTrials = 120;
        [Header("Scene")]
        [SerializeField] PseudoHapticWeight _left;
        [SerializeField] PseudoHapticWeight _right;
        [SerializeField] DiscriminationButton _leftButton;
        [SerializeField] DiscriminationButton _rightButton;
        [Tooltip("Shows the instructions and progress; optional.")]
        [SerializeField] TextMesh _display;
        [Header("Poking")]
        [SerializeField] float _cooldown = (float)PokeDebounce.DefaultCooldown;
        [SerializeField] float _releaseTime = (float)PokeDebounce.DefaultReleaseTime;

        DiscriminationTaskModel _model;
        SaveLifecycle _saves; // a pause, quitting, the end: waiting for the answer being written

        public DiscriminationTaskModel Model => _model ?? (_model = CreateModel());
        public DiscriminationSession Session => Model.Session;
        public string Error => Model.Error;
        public string Participant { get => _participant; set => _participant = value; }
        public string Condition { get => _condition; set => _condition = value; }
        /// <summary>The study's seed (each participant and condition draws its own order from it); set it before the session begins.</summary>
        public int Seed { get => _seed; set => _seed = value; }

        /// <summary>Sets the scene's objects in code (scene builders, tests).</summary>
        public void Inject(PseudoHapticWeight left, PseudoHapticWeight right, DiscriminationButton leftButton, DiscriminationButton rightButton, TextMesh display)
        {
            _left = left;
            _right = right;
            _leftButton = leftButton;
            _rightButton = rightButton;
            _display = display;
        }

        /// <summary>The trials file as set (a relative path is taken under Kosmos.PseudoHaptic in persistentDataPath).</summary>
        public string TrialsFile { get => _trialsFile; set => _trialsFile = value; }

        /// <summary>The trials file's full path.</summary>
        public string TrialsPath => DiscriminationTaskModel.TrialsPath(_trialsFile, Application.persistentDataPath);

        DiscriminationTaskModel CreateModel()
        {
            // Answers are written on a background thread, in order; the next trial comes when Update delivers the acknowledgement.
            var model = new DiscriminationTaskModel(_cooldown, _releaseTime, new SaveQueue(background: true));
            model.Failed += e =>
            {
                Debug.LogError("Discrimination task '" + name + "': " + e, this);
                Show();
            };
            model.Saved += () => Shown(Applied()); // the answer is on disk: the next trial's masses
            return model;
        }

        void Update()
        {
            if (_model != null) _model.Update();
        }

        /// <summary>Waits up to <paramref name="timeoutMs"/> for the answer being written and shows the result (a pause, quitting, a test). True when nothing is left unsaved.</summary>
        public bool WaitForSaves(int timeoutMs = SaveLifecycle.TimeoutMs) => Saves.Wait(timeoutMs);

        SaveLifecycle Saves => _saves ?? (_saves = new SaveLifecycle(() => _model?.Saver, Show));
        void OnApplicationPause(bool paused) => Saves.OnPause(paused);
        void OnApplicationQuit() => Saves.OnQuit();
        void OnDestroy() => Saves.OnDestroy();

        void Awake()
        {
            if (_leftButton != null) _leftButton.Initialize(this, PairSide.Left);
            if (_rightButton != null) _rightButton.Initialize(this, PairSide.Right);
            RememberHomes();
        }

        void OnEnable() => PseudoHapticWeight.HoldBegan += OnHoldBegan;

        void OnDisable() => PseudoHapticWeight.HoldBegan -= OnHoldBegan;

        void Start()
        {
            if (_beginOnStart && !string.IsNullOrEmpty(_participant)) Begin();
            else Show();
        }

        /// <summary>Begins or resumes the session of <see cref="Participant"/> in <see cref="Condition"/>. False (and <see cref="Error"/>) when it cannot.</summary>
        public bool Begin() => Shown(Model.Begin(ObjectsError, Settings, _participant, _condition, TrialsPath) && Applied());

        /// <summary>A fingertip's contact with a button begins: a poke answers (see <see cref="PokeDebounce"/>).</summary>
        public void Touch(DiscriminationButton button, double now)
        {
            if (button != null && Model.Touch(now)) Answer(button.Side);
        }

        /// <summary>A fingertip's contact with a button lasts.</summary>
        public void Stay(double now) => Model.Stay(now);

        /// <summary>
        /// Answers "the object on <paramref name="heavier"/> was heavier". True when the answer was taken: it is written
        /// in the background and the next trial is shown when it is on disk; false when none is taken now, or its write
        /// failed (then it is kept, shown as not saved, and written again until it is).
        /// </summary>
        public bool Answer(PairSide heavier)
            => Shown(Model.Answer(heavier, AnyHeld));

        bool Shown(bool result)
        {
            Show();
            return result;
        }

        void Show()
        {
            if (_display != null) _display.text = Model.DisplayText();
        }
    }
}
