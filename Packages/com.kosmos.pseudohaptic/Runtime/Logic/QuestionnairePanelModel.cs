using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic
{
    /// <summary>What a button of the questionnaire panel stands for.</summary>
    public enum PanelAction
    {
        /// <summary>Answers the current item with the button's value.</summary>
        Answer,
        /// <summary>Goes back to the previous item.</summary>
        Back,
        /// <summary>Goes on to the next item without changing the answer.</summary>
        Next,
    }

    /// <summary>Everything the panel shows at one moment, computed from the session (texts already wrapped).</summary>
    public struct PanelView
    {
        public string Title, Progress, Instructions, Main, MinLabel, MaxLabel, Message;
        /// <summary>Scale buttons shown, and the value of the first.</summary>
        public int Points, ScaleMin;
        /// <summary>The answer already given to the current item, if any: its button is drawn as chosen.</summary>
        public int? Chosen;
        public bool CanBack, CanNext;
    }

    /// <summary>
    /// The in-headset questionnaire panel's decisions, engine-free: starting or resuming a participant's
    /// <see cref="QuestionnaireSession"/> (paging, resume and the responses file are the session's), what a press
    /// does (answer, back, next), what a failed save says, when <see cref="Completed"/> is raised, the poke debounce,
    /// and what the panel shows (<see cref="View"/>) and where its scale buttons go (<see cref="ScaleLayout"/>).
    /// </summary>
    public sealed class QuestionnairePanelModel
    {
        /// <summary>Font size of the panel's 3D text; <see cref="CharsPerLine"/> assumes it.</summary>
        public const int FontSize = 48;
        public const float Margin = 0.03f, ButtonHeight = 0.06f, ButtonGap = 0.01f, ScaleRowY = -0.04f;

        bool _completedRaised;

        public string WaitingText = "Please wait for the experimenter.";
        public string DoneText = "Thank you. All your answers are saved.";
        public string NotSavedText = DefaultNotSavedText;
        public string SavingText = "Saving…";
        public const string DefaultNotSavedText = "That answer could not be saved yet. It is kept and tried again; please tell the experimenter.";

        public QuestionnaireSession Session { get; private set; }
        /// <summary>Why the panel cannot run or the last answer was not saved; null when all is well.</summary>
        public string Error { get; private set; }
        public PokeDebounce Debounce { get; }

        /// <summary>Raised once when the last item has been answered; after each saved answer; with a message when something failed.</summary>
        public event Action<QuestionnaireSession> Completed, Answered;
        public event Action<string> Failed;

        /// <summary>The one writer of the responses file: answers are written in order, acknowledged by <see cref="Update"/>.</summary>
        public SaveQueue Saver { get; }

        /// <summary>An answer was given and is not yet on disk (being written, or failed and waiting to be tried again).</summary>
        public bool IsSaving => Session != null && Session.IsSaving;

        /// <param name="saver">
        /// Writes the file; default one that writes inside <see cref="Answer"/> and <see cref="Update"/> on the caller's
        /// thread. The headset passes one writing in the background (<c>new SaveQueue(background: true)</c>).
        /// </param>
        public QuestionnairePanelModel(double cooldown = PokeDebounce.DefaultCooldown, double releaseTime = PokeDebounce.DefaultReleaseTime, SaveQueue saver = null)
        {
            Debounce = new PokeDebounce(Math.Max(0, cooldown), Math.Max(0, releaseTime));
            Saver = saver ?? new SaveQueue(background: false);
        }

        /// <summary>Every frame (main thread): delivers finished writes and retries a failed one. True when an answer was saved (the page changed).</summary>
        public bool Update() => Saver.Pump() > 0;

        /// <summary>Waits up to <paramref name="timeoutMs"/> for the answer being written (a pause, quitting). True when nothing is left unsaved.</summary>
        public bool Flush(int timeoutMs = 5000) => Saver.Drain(timeoutMs);

        /// <summary>Starts or resumes a session over named JSON definitions ("immersion.json", text); false, with <see cref="Error"/>, when they or the file cannot be used.</summary>
        public bool Begin(IReadOnlyList<KeyValuePair<string, string>> definitions, string participant, string responsesPath, IEnumerable<string> ids)
        {
            // Before the session is dropped: the guard reads whether it has an answer still unsaved.
            if (RefusesWhileUnsaved()) return false;
            Session = null; // a failed begin shows its reason, not the last participant's page
            if (definitions == null || definitions.Count == 0) return Fail("no questionnaire definitions are assigned to the panel");
            QuestionnaireCatalog catalog;
            try
            {
                catalog = QuestionnaireJson.ParseAll(definitions);
            }
            catch (EvaluationFormatException e)
            {
                return Fail(e.Message);
            }
            return Begin(catalog, participant, responsesPath, ids);
        }

        /// <summary>Starts or resumes <paramref name="participant"/>'s session; false, with <see cref="Error"/>, when the catalog or the file cannot be used.</summary>
        public bool Begin(QuestionnaireCatalog catalog, string participant, string responsesPath, IEnumerable<string> ids)
        {
            if (RefusesWhileUnsaved()) return false;
            Session = null;
            _completedRaised = false;
            Debounce.Reset();
            try
            {
                Session = new QuestionnaireSession(catalog, participant, responsesPath, ids);
            }
            catch (Exception e) when (e is EvaluationFormatException || e is ArgumentException || e is IOException || e is UnauthorizedAccessException)
            {
                return Fail(e.Message);
            }
            Error = null;
            _completedRaised = Session.IsComplete;
            return true;
        }

        /// <summary>An answer of the current session is not on disk and cannot be written now: a new session would read the
        /// responses file without it and write over it, so the begin is refused, the page and the answer kept.</summary>
        bool RefusesWhileUnsaved()
        {
            if (!IsSaving || Saver.Drain()) return false;
            Fail("the last answer is not saved yet: " + Saver.LastError);
            return true;
        }

        bool Fail(string error)
        {
            Error = error;
            Failed?.Invoke(error);
            return false;
        }

        /// <summary>A fingertip's contact with a button begins: true when it counts as a poke (see <see cref="PokeDebounce"/>).</summary>
        public bool Touch(double now) => Debounce.Touch(now);

        /// <summary>A fingertip's contact lasts.</summary>
        public void Stay(double now) => Debounce.Stay(now);

        /// <summary>A poke that selected the panel's surface (the Interaction SDK's): true when it is not within the cooldown.</summary>
        public bool Poke(double now) => Debounce.Press(now);

        /// <summary>Does what a button stands for, without the debounce. True when something changed.</summary>
        public bool Press(PanelAction action, int value)
        {
            if (Session == null) return false;
            if (action == PanelAction.Answer) return Answer(value);
            bool changed = action == PanelAction.Back ? Session.Back() : Session.Forward();
            if (changed) Error = null;
            return changed;
        }

        /// <summary>
        /// Answers the current item: the answer is taken into memory and its write queued; the page moves on only when
        /// the write returned (<see cref="Answered"/>, delivered here or by <see cref="Update"/>). True when the answer
        /// was taken and nothing failed (saved, or being saved); false when none is taken now (no session, finished,
        /// the last answer still being saved, a value off the scale) or its write failed: then <see cref="Error"/> says
        /// so, the answer is kept, and it is written again every <see cref="SaveQueue.RetrySeconds"/> until it is saved.
        /// </summary>
        public bool Answer(int value)
        {
            if (Session == null || Session.IsFinished || Session.IsSaving) return false;
            var session = Session;
            try
            {
                session.Submit(value);
            }
            catch (ArgumentOutOfRangeException e)
            {
                return Fail(e.Message);
            }
            string path = session.ResponsesPath, text = session.FileText();
            Saver.Enqueue(() => DiscriminationSession.Save(path, text), () => Acknowledged(session), e => Fail(e));
            Saver.Pump();
            return Error == null;
        }

        void Acknowledged(QuestionnaireSession session)
        {
            session.Acknowledge();
            if (session != Session) return;
            Error = null;
            Answered?.Invoke(session);
            if (session.IsComplete && !_completedRaised)
            {
                _completedRaised = true;
                Completed?.Invoke(session);
            }
        }

        /// <summary>What the panel shows, its texts wrapped for a panel <paramref name="width"/> m wide at <paramref name="textSize"/>.</summary>
        public PanelView View(float width, float textSize)
        {
            QuestionnaireSession s = Session;
            bool asking = s != null && !s.IsFinished;
            Questionnaire q = asking ? s.CurrentQuestionnaire : null;
            float inner = width - 2 * Margin;
            float small = textSize * 0.75f;
            int points = q != null ? q.ScaleMax - q.ScaleMin + 1 : 0;
            float labelWidth = points > 0 ? Math.Max(0.12f, inner / 2 - 0.02f) : 0;
            string main = s == null ? Error ?? WaitingText : !asking ? DoneText : s.CurrentItem.Text;
            return new PanelView
            {
                Title = q != null ? q.Title : "",
                Progress = asking ? s.ProgressText : "",
                Instructions = q != null ? TextWrap.Wrap(q.Instructions, CharsPerLine(inner, small)) : "",
                Main = TextWrap.Wrap(main, CharsPerLine(inner, textSize)),
                MinLabel = q != null ? TextWrap.Wrap(q.ScaleMinLabel, CharsPerLine(labelWidth, small)) : "",
                MaxLabel = q != null ? TextWrap.Wrap(q.ScaleMaxLabel, CharsPerLine(labelWidth, small)) : "",
                // "Not saved, kept, tried again" only for an answer that is kept: a refused value (off the scale) keeps nothing.
                Message = s == null || !s.IsSaving ? ""
                    : TextWrap.Wrap(Error != null ? NotSavedText : SavingText, CharsPerLine(inner, small)),
                Points = points,
                ScaleMin = q != null ? q.ScaleMin : 0,
                Chosen = asking ? s.CurrentAnswer : null,
                CanBack = s != null && s.CanGoBack,
                CanNext = s != null && s.CanGoForward,
            };
        }

        /// <summary>Characters that fit a line of <paramref name="width"/> m at <paramref name="characterSize"/> (a legacy font's glyphs average about half their line height).</summary>
        public static int CharsPerLine(float width, float characterSize)
        {
            float lineHeight = characterSize * FontSize / 10f;
            float charWidth = 0.55f * lineHeight;
            return Math.Max(8, (int)(width / charWidth * 0.9f));
        }

        /// <summary>
        /// Where scale button <paramref name="index"/> of <paramref name="points"/> goes on a panel <paramref name="width"/> m
        /// wide: its centre's x and its width (at most 8 cm, side by side with 1 cm gaps, centred); <paramref name="edge"/>
        /// is the row's half width, where the end labels sit.
        /// </summary>
        public static float ScaleLayout(int index, int points, float width, out float buttonWidth, out float edge)
        {
            float usable = width - 2 * Margin;
            buttonWidth = points > 0 ? Math.Min(0.08f, (usable - (points - 1) * ButtonGap) / points) : 0;
            float total = points * buttonWidth + Math.Max(0, points - 1) * ButtonGap;
            edge = total / 2;
            return -total / 2 + buttonWidth / 2 + index * (buttonWidth + ButtonGap);
        }

        /// <summary>The label of a scale button of value <paramref name="value"/>.</summary>
        public static string Label(int value) => value.ToString(CultureInfo.InvariantCulture);
    }
}
