using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A world-space questionnaire panel answered by poking with the tracked hand: one item per page, title and
    /// progress at the top, one button per point of the scale with its end labels, Back and Next at the bottom.
    /// Glue over the engine-free <see cref="QuestionnairePanelModel"/> (session, paging and resume, presses, the
    /// debounce, what is shown): this reads the assigned JSON assets, forwards pokes from <see cref="PokeButton"/>s or
    /// the Interaction SDK (<see cref="PokeAt"/>), and writes the view into primitives built by
    /// <see cref="QuestionnairePanelParts"/>. The panel faces −z; its own scale should be 1 (sizes are in metres).
    /// Its look (sizes, parts, the texts shown): QuestionnairePanel.Look.cs.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Questionnaire Panel")]
    public sealed partial class QuestionnairePanel : MonoBehaviour
    {
        [Header("Questionnaires")]
        [Tooltip("The questionnaire definitions (JSON), in report order: the package's Runtime/Evaluation/Questionnaires/*.json, or translated copies.")]
        [SerializeField] TextAsset[] _questionnaires = new TextAsset[0];
        [Tooltip("Ids of the questionnaires to ask, in order; empty: all of them in the order above.")]
        [SerializeField] string[] _ask = new string[0];
        [Header("Participant and file")]
        [Tooltip("The participant's id as the responses file names it.")]
        [SerializeField] string _participant = "";
        [Tooltip("Begin (or resume) at Start when a participant is set; otherwise call Begin from code.")]
        [SerializeField] bool _beginOnStart = true;
        [Tooltip("The responses file; a relative path is taken under Kosmos.PseudoHaptic in Application.persistentDataPath.")]
        [SerializeField] string _responsesFile = "responses.csv";
        [Header("Poking")]
        [Tooltip("Shortest time between two answers, s.")]
        [SerializeField] float _cooldown = (float)PokeDebounce.DefaultCooldown;
        [Tooltip("How long the fingertip must have left every button before it can poke again, s.")]
        [SerializeField] float _releaseTime = (float)PokeDebounce.DefaultReleaseTime;
        [Header("Look")]
        [Tooltip("Width and height of the panel, m.")]
        [SerializeField] Vector2 _size = new Vector2(0.6f, 0.42f);
        [Tooltip("Character size of the item text (3D text at font size 48; 0.004 is about 2 cm a line).")]
        [SerializeField] float _textSize = 0.004f;
        [SerializeField] Color _panelColor = new Color(0.13f, 0.14f, 0.16f);
        [SerializeField] Color _textColor = new Color(1f, 1f, 1f);
        [SerializeField] Color _buttonColor = new Color(0.86f, 0.87f, 0.9f);
        [SerializeField] Color _chosenColor = new Color(0.33f, 0.62f, 1f);
        [SerializeField] Color _buttonTextColor = new Color(0.05f, 0.05f, 0.08f);
        [Header("Words")]
        [SerializeField] string _backText = "Back";
        [SerializeField] string _nextText = "Next";
        [SerializeField] string _waitingText = "Please wait for the experimenter.";
        [SerializeField] string _doneText = "Thank you. All your answers are saved.";
        [SerializeField] string _notSavedText = QuestionnairePanelModel.DefaultNotSavedText;
        [SerializeField] string _savingText = "Saving…";

        QuestionnairePanelModel _model;
        SaveLifecycle _saves; // a pause, quitting, the end: waiting for the answer being written

        public QuestionnairePanelModel Model => _model ?? (_model = CreateModel());
        public QuestionnaireSession Session => Model.Session; // null before Begin
        public string Error => Model.Error; // why the panel cannot run or the last answer was not saved; null when all is well
        public PokeDebounce Debounce => Model.Debounce;

        /// <summary>Raised once when the last item has been answered; after each answer is saved.</summary>
        public event Action<QuestionnaireSession> Completed, Answered;

        public void InjectQuestionnaires(params TextAsset[] definitions) => _questionnaires = definitions ?? new TextAsset[0];
        public string[] Ask { get => _ask; set => _ask = value ?? new string[0]; }

        public string Participant { get => _participant; set => _participant = value ?? ""; }
        public string ResponsesFile { get => _responsesFile; set => _responsesFile = value ?? ""; }

        /// <summary>The responses file's full path.</summary>
        public string ResponsesPath => Path.Combine(Application.persistentDataPath, "Kosmos.PseudoHaptic",
            string.IsNullOrEmpty(_responsesFile) ? "responses.csv" : _responsesFile); // a rooted file is kept as it is

        QuestionnairePanelModel CreateModel()
        {
            // Answers are written on a background thread, in order; the page turns when Update delivers the acknowledgement.
            var model = new QuestionnairePanelModel(_cooldown, _releaseTime, new SaveQueue(background: true))
                { WaitingText = _waitingText, DoneText = _doneText, NotSavedText = _notSavedText, SavingText = _savingText };
            model.Completed += s => Completed?.Invoke(s);
            model.Answered += s => Answered?.Invoke(s);
            model.Failed += e =>
            {
                Debug.LogError("Questionnaire panel '" + name + "': " + e, this);
                Show();
            };
            return model;
        }

        void Update()
        {
            if (_model != null && _model.Update()) Show(); // an answer is on disk: the next page
        }

        /// <summary>Waits up to <paramref name="timeoutMs"/> for the answer being written and shows the result (a pause, quitting, a test). True when nothing is left unsaved.</summary>
        public bool WaitForSaves(int timeoutMs = SaveLifecycle.TimeoutMs) => Saves.Wait(timeoutMs);

        SaveLifecycle Saves => _saves ?? (_saves = new SaveLifecycle(() => _model?.Saver, Show));
        void OnApplicationPause(bool paused) => Saves.OnPause(paused);
        void OnApplicationQuit() => Saves.OnQuit();
        void OnDestroy() => Saves.OnDestroy();

        void Start()
        {
            if (Session == null && _beginOnStart && !string.IsNullOrWhiteSpace(_participant)) Begin(_participant);
            Show();
        }

        /// <summary>Starts or resumes <paramref name="participant"/>'s questionnaires from the assigned JSON; false, with <see cref="Error"/> shown, when it cannot.</summary>
        public bool Begin(string participant)
        {
            var named = new List<KeyValuePair<string, string>>();
            foreach (TextAsset asset in _questionnaires)
                if (asset != null) named.Add(new KeyValuePair<string, string>(asset.name + ".json", asset.text));
            _participant = participant ?? "";
            return Shown(Model.Begin(named, participant, ResponsesPath, _ask != null && _ask.Length > 0 ? _ask : null));
        }

        /// <summary>Starts or resumes a session over a catalog given in code (tests, custom loaders).</summary>
        public bool Begin(QuestionnaireCatalog catalog, string participant, IEnumerable<string> questionnaireIds = null)
        {
            _participant = participant ?? "";
            return Shown(Model.Begin(catalog, participant, ResponsesPath, questionnaireIds));
        }

        /// <summary>A fingertip's contact with <paramref name="button"/> begins: a poke presses it.</summary>
        public void Touch(PokeButton button, double now)
        {
            if (Model.Touch(now)) Press(button);
        }

        public void Stay(double now) => Model.Stay(now); // a fingertip's contact with a button lasts

        /// <summary>A poke that selected the panel's surface at <paramref name="world"/> (the Interaction SDK's): presses the button there, if any, outside the cooldown.</summary>
        public bool PokeAt(Vector3 world, double now)
        {
            PokeButton button = ButtonAt(world);
            return button != null && Model.Poke(now) && Press(button);
        }

        public PokeButton ButtonAt(Vector3 world) => Parts.ButtonAt(world); // the active button whose face contains it, or null

        /// <summary>Does what <paramref name="button"/> stands for, without the debounce. True when something changed.</summary>
        public bool Press(PokeButton button) => button != null && Shown(Model.Press(button.Kind, button.Value));

        /// <summary>Answers the current item (as a poke on that button would). True when the answer was taken (it is saved in the background and the page turns when it is); false when not, or its write failed (then kept and tried again).</summary>
        public bool Answer(int value) => Shown(Model.Answer(value));

        bool Shown(bool result)
        {
            Show();
            return result;
        }

    }
}
