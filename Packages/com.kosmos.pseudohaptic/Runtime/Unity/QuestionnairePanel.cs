using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A world-space questionnaire panel answered by poking with the tracked hand: one item per page, the
    /// questionnaire's title and the progress ("3 / 10") at the top, the item in the middle, one button per
    /// point of the scale with the scale's end labels under it, Back and Next at the bottom. Built at run time
    /// from cubes, quads and 3D text (no UI package). Every answer goes to the responses file at once,
    /// through <see cref="QuestionnaireSession"/>, which holds all of the logic: this component only shows
    /// its state and forwards pokes. Poked by a <see cref="FingertipPoker"/> (trigger contacts, debounced by
    /// <see cref="PokeDebounce"/>) or, with the Interaction SDK, by its poke through
    /// <c>QuestionnairePokeSurface</c> (<see cref="PokeAt"/>).
    /// </summary>
    /// <remarks>
    /// The panel faces −z: place it so that its blue axis points away from the participant. Its own scale
    /// should be 1 (sizes are in metres).
    /// </remarks>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Questionnaire Panel")]
    public sealed class QuestionnairePanel : MonoBehaviour
    {
        const int FontSize = 48;

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
        [SerializeField] string _notSavedText = "That answer could not be saved. Please tell the experimenter.";

        QuestionnaireSession _session;
        PokeDebounce _debounce;
        string _error;
        bool _built, _completedRaised;
        Font _font;
        Renderer _background;
        TextMesh _title, _progress, _instructions, _item, _minLabel, _maxLabel, _message;
        readonly List<PokeButton> _scale = new List<PokeButton>();
        PokeButton _back, _next;

        /// <summary>The running session; null before <see cref="Begin(string)"/>.</summary>
        public QuestionnaireSession Session => _session;

        /// <summary>Why the panel cannot run or the last answer was not saved; null when all is well.</summary>
        public string Error => _error;

        /// <summary>The buttons of the scale shown (the first <see cref="QuestionnaireSession.CurrentQuestionnaire"/>'s scale count are active).</summary>
        public IReadOnlyList<PokeButton> ScaleButtons => _scale;
        public PokeButton BackButton => _back;
        public PokeButton NextButton => _next;

        /// <summary>The texts shown, for tests and tools: title, progress, item, scale labels, message.</summary>
        public string TitleText => _title != null ? _title.text : "";
        public string ProgressText => _progress != null ? _progress.text : "";
        public string ItemText => _item != null ? _item.text : "";
        public string MinLabelText => _minLabel != null ? _minLabel.text : "";
        public string MaxLabelText => _maxLabel != null ? _maxLabel.text : "";
        public string MessageText => _message != null ? _message.text : "";

        /// <summary>Raised once when the last item has been answered.</summary>
        public event Action<QuestionnaireSession> Completed;

        /// <summary>Raised after each answer is saved.</summary>
        public event Action<QuestionnaireSession> Answered;

        /// <summary>Sets the questionnaire definitions (JSON text assets) in code, in report order.</summary>
        public void InjectQuestionnaires(params TextAsset[] definitions) => _questionnaires = definitions ?? new TextAsset[0];

        /// <summary>Ids of the questionnaires to ask, in order; null or empty: all of them.</summary>
        public string[] Ask
        {
            get => _ask;
            set => _ask = value ?? new string[0];
        }

        public string Participant
        {
            get => _participant;
            set => _participant = value ?? "";
        }

        /// <summary>The responses file as set (relative or absolute).</summary>
        public string ResponsesFile
        {
            get => _responsesFile;
            set => _responsesFile = value ?? "";
        }

        /// <summary>The responses file's full path.</summary>
        public string ResponsesPath
        {
            get
            {
                string file = string.IsNullOrEmpty(_responsesFile) ? "responses.csv" : _responsesFile;
                return Path.IsPathRooted(file) ? file : Path.Combine(Application.persistentDataPath, "Kosmos.PseudoHaptic", file);
            }
        }

        public PokeDebounce Debounce => _debounce ?? (_debounce = new PokeDebounce(Math.Max(0f, _cooldown), Math.Max(0f, _releaseTime)));

        void Start()
        {
            if (_session != null) return;
            if (_beginOnStart && !string.IsNullOrWhiteSpace(_participant)) Begin(_participant);
            else Show();
        }

        /// <summary>
        /// Starts or resumes <paramref name="participant"/>'s questionnaires from the assigned JSON definitions.
        /// False, with <see cref="Error"/> set and shown, when the definitions or the responses file cannot be used.
        /// </summary>
        public bool Begin(string participant)
        {
            QuestionnaireCatalog catalog;
            try
            {
                var named = new List<KeyValuePair<string, string>>();
                foreach (TextAsset asset in _questionnaires)
                    if (asset != null) named.Add(new KeyValuePair<string, string>(asset.name + ".json", asset.text));
                if (named.Count == 0) return Fail("no questionnaire definitions are assigned to the panel");
                catalog = QuestionnaireJson.ParseAll(named);
            }
            catch (EvaluationFormatException e)
            {
                return Fail(e.Message);
            }
            return Begin(catalog, participant, _ask != null && _ask.Length > 0 ? _ask : null);
        }

        /// <summary>Starts or resumes a session over a catalog given in code (tests, custom loaders).</summary>
        public bool Begin(QuestionnaireCatalog catalog, string participant, IEnumerable<string> questionnaireIds = null)
        {
            _participant = participant ?? "";
            _session = null;
            _completedRaised = false;
            Debounce.Reset();
            try
            {
                _session = new QuestionnaireSession(catalog, participant, ResponsesPath, questionnaireIds);
            }
            catch (Exception e) when (e is EvaluationFormatException || e is ArgumentException || e is IOException || e is UnauthorizedAccessException)
            {
                return Fail(e.Message);
            }
            _error = null;
            _completedRaised = _session.IsComplete;
            Show();
            return true;
        }

        bool Fail(string error)
        {
            _error = error;
            Debug.LogError("Questionnaire panel '" + name + "': " + error, this);
            Show();
            return false;
        }

        /// <summary>A fingertip's contact with <paramref name="button"/> begins: a poke presses it (see <see cref="PokeDebounce"/>).</summary>
        public void Touch(PokeButton button, double now)
        {
            if (Debounce.Touch(now)) Press(button);
        }

        /// <summary>A fingertip's contact with a button lasts.</summary>
        public void Stay(double now) => Debounce.Stay(now);

        /// <summary>
        /// A poke that selected the panel's surface at <paramref name="world"/> (the Interaction SDK's poke): presses the
        /// button there, if any, unless it comes within the cooldown of the last poke. True when a button was pressed.
        /// </summary>
        public bool PokeAt(Vector3 world, double now)
        {
            PokeButton button = ButtonAt(world);
            return button != null && Debounce.Press(now) && Press(button);
        }

        /// <summary>The active button whose face contains <paramref name="world"/>, or null.</summary>
        public PokeButton ButtonAt(Vector3 world)
        {
            for (int i = 0; i < _scale.Count; i++)
                if (_scale[i].gameObject.activeSelf && _scale[i].Contains(world)) return _scale[i];
            if (_back != null && _back.gameObject.activeSelf && _back.Contains(world)) return _back;
            if (_next != null && _next.gameObject.activeSelf && _next.Contains(world)) return _next;
            return null;
        }

        /// <summary>Does what <paramref name="button"/> stands for, without the debounce. True when something changed.</summary>
        public bool Press(PokeButton button)
        {
            if (_session == null || button == null) return false;
            if (button.Kind == PokeButton.Role.Answer) return Answer(button.Value);
            bool changed = button.Kind == PokeButton.Role.Back ? _session.Back() : _session.Forward();
            if (changed) _error = null;
            Show();
            return changed;
        }

        /// <summary>Answers the current item (as a poke on that button would). True when the answer was saved.</summary>
        public bool Answer(int value)
        {
            if (_session == null || _session.IsFinished) return false;
            try
            {
                _session.Answer(value);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentOutOfRangeException)
            {
                _error = e.Message;
                Debug.LogError("Questionnaire panel '" + name + "': the answer was not saved: " + e.Message, this);
                Show();
                return false;
            }
            _error = null;
            Answered?.Invoke(_session);
            if (_session.IsComplete && !_completedRaised)
            {
                _completedRaised = true;
                Completed?.Invoke(_session);
            }
            Show();
            return true;
        }

        /// <summary>Shows the session's current state (Begin, Press and Answer call it).</summary>
        public void Show()
        {
            Build();
            QuestionnaireSession s = _session;
            bool asking = s != null && !s.IsFinished;
            Questionnaire q = asking ? s.CurrentQuestionnaire : null;
            int points = q != null ? q.ScaleMax - q.ScaleMin + 1 : 0;
            LayOutScale(points);

            float width = _size.x - 2 * Margin;
            _title.text = q != null ? q.Title : "";
            _progress.text = asking ? s.ProgressText : "";
            _instructions.text = q != null ? TextWrap.Wrap(q.Instructions, CharsPerLine(width, _textSize * 0.75f)) : "";

            string main;
            if (s == null) main = _error ?? _waitingText;
            else if (!asking) main = _doneText;
            else main = s.CurrentItem.Text;
            _item.text = TextWrap.Wrap(main, CharsPerLine(width, _textSize));

            int? chosen = asking ? s.CurrentAnswer : null;
            for (int i = 0; i < _scale.Count; i++)
            {
                PokeButton b = _scale[i];
                bool active = i < points;
                if (b.gameObject.activeSelf != active) b.gameObject.SetActive(active);
                if (!active) continue;
                b.Value = q.ScaleMin + i;
                b.Label.text = b.Value.ToString(System.Globalization.CultureInfo.InvariantCulture);
                Tint(b.Face, chosen.HasValue && chosen.Value == b.Value ? _chosenColor : _buttonColor);
            }
            float labelWidth = points > 0 ? Math.Max(0.12f, width / 2 - 0.02f) : 0;
            _minLabel.text = q != null ? TextWrap.Wrap(q.ScaleMinLabel, CharsPerLine(labelWidth, _textSize * 0.75f)) : "";
            _maxLabel.text = q != null ? TextWrap.Wrap(q.ScaleMaxLabel, CharsPerLine(labelWidth, _textSize * 0.75f)) : "";

            SetActive(_back, s != null && s.CanGoBack);
            SetActive(_next, s != null && s.CanGoForward);
            _message.text = s != null && _error != null ? TextWrap.Wrap(_notSavedText, CharsPerLine(width, _textSize * 0.75f)) : "";
        }

        static void SetActive(PokeButton button, bool active)
        {
            if (button.gameObject.activeSelf != active) button.gameObject.SetActive(active);
        }

        const float Margin = 0.03f;
        const float ButtonHeight = 0.06f;
        const float ButtonGap = 0.01f;
        const float ScaleRowY = -0.04f;

        /// <summary>Characters that fit a line of <paramref name="width"/> m at <paramref name="characterSize"/> (a legacy font's glyphs average about half their line height).</summary>
        static int CharsPerLine(float width, float characterSize)
        {
            float lineHeight = characterSize * FontSize / 10f;
            float charWidth = 0.55f * lineHeight;
            return Math.Max(8, (int)(width / charWidth * 0.9f));
        }

        void Build()
        {
            if (_built) return;
            _built = true;
            // Unity 2022.2+ ships its legacy font as LegacyRuntime.ttf.
            _font = Resources.GetBuiltinResource<Font>("LegacyRuntime.ttf");

            var background = GameObject.CreatePrimitive(PrimitiveType.Quad);
            background.name = "Background";
            background.GetComponent<Collider>().enabled = false;
            background.transform.SetParent(transform, false);
            background.transform.localPosition = new Vector3(0, 0, 0.006f);
            background.transform.localScale = new Vector3(_size.x, _size.y, 1);
            _background = background.GetComponent<Renderer>();
            Tint(_background, _panelColor);

            float left = -_size.x / 2 + Margin, right = _size.x / 2 - Margin, top = _size.y / 2 - Margin;
            _title = Text("Title", new Vector3(left, top, 0), TextAnchor.UpperLeft, TextAlignment.Left, _textSize * 0.85f, _textColor);
            _progress = Text("Progress", new Vector3(right, top, 0), TextAnchor.UpperRight, TextAlignment.Right, _textSize * 0.85f, _textColor);
            _instructions = Text("Instructions", new Vector3(left, top - 0.035f, 0), TextAnchor.UpperLeft, TextAlignment.Left, _textSize * 0.75f, _textColor);
            _item = Text("Item", new Vector3(0, 0.07f, 0), TextAnchor.MiddleCenter, TextAlignment.Center, _textSize, _textColor);
            float labelsY = ScaleRowY - ButtonHeight / 2 - 0.01f;
            _minLabel = Text("Scale Min Label", new Vector3(left, labelsY, 0), TextAnchor.UpperLeft, TextAlignment.Left, _textSize * 0.75f, _textColor);
            _maxLabel = Text("Scale Max Label", new Vector3(right, labelsY, 0), TextAnchor.UpperRight, TextAlignment.Right, _textSize * 0.75f, _textColor);
            float bottom = -_size.y / 2 + Margin + 0.025f;
            _message = Text("Message", new Vector3(0, bottom, 0), TextAnchor.MiddleCenter, TextAlignment.Center, _textSize * 0.75f, _chosenColor);

            _back = Button("Back", PokeButton.Role.Back, new Vector3(left + 0.06f, bottom, 0), new Vector2(0.12f, 0.05f), _backText);
            _next = Button("Next", PokeButton.Role.Next, new Vector3(right - 0.06f, bottom, 0), new Vector2(0.12f, 0.05f), _nextText);
        }

        /// <summary>Places <paramref name="points"/> scale buttons side by side, centred, making more if needed.</summary>
        void LayOutScale(int points)
        {
            if (points <= 0) return;
            while (_scale.Count < points)
                _scale.Add(Button("Answer " + (_scale.Count + 1), PokeButton.Role.Answer, Vector3.zero, new Vector2(0.05f, ButtonHeight), ""));
            float usable = _size.x - 2 * Margin;
            float width = Math.Min(0.08f, (usable - (points - 1) * ButtonGap) / points);
            float total = points * width + (points - 1) * ButtonGap;
            for (int i = 0; i < points; i++)
            {
                PokeButton b = _scale[i];
                b.transform.localPosition = new Vector3(-total / 2 + width / 2 + i * (width + ButtonGap), ScaleRowY, 0);
                Resize(b, new Vector2(width, ButtonHeight));
            }
            // The end labels sit under the first and last buttons.
            float edge = total / 2;
            _minLabel.transform.localPosition = new Vector3(-edge, _minLabel.transform.localPosition.y, 0);
            _maxLabel.transform.localPosition = new Vector3(edge, _maxLabel.transform.localPosition.y, 0);
        }

        // The colours go through a property block: the primitives keep sharing Unity's default material (renderer.material
        // would copy it per object, and leak those copies when called in edit mode). _Color is the built-in pipeline's
        // colour, _BaseColor URP's; a shader ignores the one it lacks.
        static readonly int ColorId = Shader.PropertyToID("_Color");
        static readonly int BaseColorId = Shader.PropertyToID("_BaseColor");
        static MaterialPropertyBlock s_tint;

        static void Tint(Renderer renderer, Color color)
        {
            if (s_tint == null) s_tint = new MaterialPropertyBlock();
            s_tint.SetColor(ColorId, color);
            s_tint.SetColor(BaseColorId, color);
            renderer.SetPropertyBlock(s_tint);
        }

        TextMesh Text(string objectName, Vector3 localPosition, TextAnchor anchor, TextAlignment alignment, float characterSize, Color color)
        {
            var go = new GameObject(objectName);
            go.transform.SetParent(transform, false);
            go.transform.localPosition = localPosition + new Vector3(0, 0, -0.002f);
            var text = go.AddComponent<TextMesh>();
            text.anchor = anchor;
            text.alignment = alignment;
            text.fontSize = FontSize;
            text.characterSize = characterSize;
            text.color = color;
            if (_font != null)
            {
                text.font = _font;
                go.GetComponent<MeshRenderer>().sharedMaterial = _font.material;
            }
            return text;
        }

        PokeButton Button(string objectName, PokeButton.Role role, Vector3 localPosition, Vector2 size, string label)
        {
            var root = new GameObject(objectName);
            root.transform.SetParent(transform, false);
            root.transform.localPosition = localPosition;
            var collider = root.AddComponent<BoxCollider>();
            collider.isTrigger = true;

            var face = GameObject.CreatePrimitive(PrimitiveType.Cube);
            face.name = "Face";
            face.GetComponent<Collider>().enabled = false;
            face.transform.SetParent(root.transform, false);
            var renderer = face.GetComponent<Renderer>();
            Tint(renderer, _buttonColor);

            var text = new GameObject("Label");
            text.transform.SetParent(root.transform, false);
            text.transform.localPosition = new Vector3(0, 0, -0.007f);
            var mesh = text.AddComponent<TextMesh>();
            mesh.anchor = TextAnchor.MiddleCenter;
            mesh.alignment = TextAlignment.Center;
            mesh.fontSize = FontSize;
            mesh.characterSize = _textSize * 0.9f;
            mesh.color = _buttonTextColor;
            mesh.text = label;
            if (_font != null)
            {
                mesh.font = _font;
                text.GetComponent<MeshRenderer>().sharedMaterial = _font.material;
            }

            var button = root.AddComponent<PokeButton>();
            button.Initialize(this, role, collider, renderer, mesh);
            Resize(button, size);
            return button;
        }

        /// <summary>The face is 1 cm thick; the trigger reaches 2.5 cm in front of it, so a fast fingertip is not missed between physics steps.</summary>
        static void Resize(PokeButton button, Vector2 size)
        {
            button.Size = size;
            button.Face.transform.localScale = new Vector3(size.x, size.y, 0.01f);
            button.Collider.size = new Vector3(size.x, size.y, 0.035f);
            button.Collider.center = new Vector3(0, 0, -0.0125f);
        }
    }
}
