using System;
using System.IO;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The in-headset discrimination task's decisions, engine-free (the component is glue over this): where the
    /// trials file is, beginning or resuming a <see cref="DiscriminationSession"/> and what a failure says, which
    /// lifted object is which side, when a poke answers (the debounce; never while an object is held), what a
    /// failed save says, and the text shown. The session itself keeps the plan, the lifts, the file and resume.
    /// </summary>
    public sealed class DiscriminationTaskModel
    {
        public const string DefaultTrialsFile = "trials.csv";
        public const string WaitingText = "Waiting for a participant.";
        public const string DoneText = "Done. Thank you!";
        public const string AnswerText = "Which was heavier? Poke the button on its side.";
        public const string LiftText = "Lift both objects, then put them down.";
        public const string SavingText = "Saving the answer…";
        /// <summary>What a failed save says, before the error (the answer is kept and written again until it is saved).</summary>
        public const string NotSavedPrefix = "the answer could not be saved: ";

        /// <summary>The session; null before a successful <see cref="Begin"/>.</summary>
        public DiscriminationSession Session { get; private set; }
        /// <summary>Why the task cannot run or the last answer was not saved; null when all is well.</summary>
        public string Error { get; private set; }
        public PokeDebounce Debounce { get; }
        /// <summary>True when a trial is under way (its masses are to be on the objects).</summary>
        public bool HasTrial => Session != null && !Session.IsFinished;

        /// <summary>Raised with the message when something fails (a failed save: each time it is tried and fails).</summary>
        public event Action<string> Failed;
        /// <summary>Raised on the main thread when an answer's write returned and the next trial is shown.</summary>
        public event Action Saved;

        /// <summary>The one writer of the trials file: answers are written in order, acknowledged by <see cref="Update"/>.</summary>
        public SaveQueue Saver { get; }

        /// <summary>An answer was given and is not yet on disk (being written, or failed and waiting to be tried again).</summary>
        public bool IsSaving => Session != null && Session.IsSaving;

        /// <param name="saver">
        /// Writes the file; default one that writes inside <see cref="Answer"/> and <see cref="Update"/> on the caller's
        /// thread. The headset passes one writing in the background (<c>new SaveQueue(background: true)</c>).
        /// </param>
        public DiscriminationTaskModel(double cooldown = PokeDebounce.DefaultCooldown, double releaseTime = PokeDebounce.DefaultReleaseTime, SaveQueue saver = null)
        {
            Debounce = new PokeDebounce(cooldown, releaseTime);
            Saver = saver ?? new SaveQueue(background: false);
        }

        /// <summary>The trials file's full path: <paramref name="file"/> (trials.csv when empty) as it is when rooted, else under Kosmos.PseudoHaptic in <paramref name="dataFolder"/>.</summary>
        public static string TrialsPath(string file, string dataFolder)
        {
            string name = string.IsNullOrEmpty(file) ? DefaultTrialsFile : file;
            return Path.IsPathRooted(name) ? name : Path.Combine(dataFolder, "Kosmos.PseudoHaptic", name);
        }

        /// <summary>
        /// Begins or resumes the session; false, with <see cref="Error"/>, when the objects are not both set or the
        /// settings, participant, condition or file cannot be used (the session is then null).
        /// </summary>
        public bool Begin(bool objectsSet, DiscriminationSettings settings, string participant, string condition, string trialsPath) =>
            Begin(objectsSet ? null : "the left and right objects are not set", settings, participant, condition, trialsPath);

        /// <summary>As <see cref="Begin(bool, DiscriminationSettings, string, string, string)"/>, with what is wrong with the objects (null: nothing).</summary>
        public bool Begin(string objectsError, DiscriminationSettings settings, string participant, string condition, string trialsPath)
        {
            if (objectsError != null) return Fail(objectsError);
            if (IsSaving && !Saver.Drain()) return Fail("the last answer is not saved yet: " + Saver.LastError);
            try
            {
                Session = settings.CreateSession(participant, condition, trialsPath);
            }
            catch (Exception e) when (e is ArgumentException || e is EvaluationFormatException || e is IOException || e is UnauthorizedAccessException)
            {
                Session = null;
                return Fail(e.Message);
            }
            Error = null;
            return true;
        }

        /// <summary>An object's hold began: notes the lift of the left or right one. True when it was one of them in a session.</summary>
        public bool NoteLift(bool isLeft, bool isRight)
        {
            if (Session == null) return false;
            if (isLeft) Session.NoteLift(PairSide.Left);
            else if (isRight) Session.NoteLift(PairSide.Right);
            else return false;
            return true;
        }

        /// <summary>A fingertip's contact with a button begins: true when it counts as a poke (see <see cref="PokeDebounce"/>).</summary>
        public bool Touch(double now) => Debounce.Touch(now);

        /// <summary>A fingertip's contact with a button lasts.</summary>
        public void Stay(double now) => Debounce.Stay(now);

        /// <summary>
        /// Answers "the object on <paramref name="heavier"/> was heavier": the answer is taken into memory and its
        /// write queued; the next trial is shown only when the write returned (<see cref="Saved"/>, delivered here or
        /// by <see cref="Update"/>). True when the answer was taken and nothing failed (saved, or being saved); false
        /// when no answer is taken now (the session is finished, an object is held, the last answer is still being
        /// saved), or when its write failed: then <see cref="Error"/> says so, the answer is kept, and it is written
        /// again every <see cref="SaveQueue.RetrySeconds"/> until it is saved (never twice, never another answer meanwhile).
        /// </summary>
        public bool Answer(PairSide heavier, bool anyHeld)
        {
            if (Session == null || !Session.CanAnswer || anyHeld) return false;
            var session = Session;
            session.Submit(heavier);
            string path = session.TrialsPath, text = session.FileText();
            Saver.Enqueue(() => DiscriminationSession.Save(path, text), () => Acknowledged(session), e => Fail(NotSavedPrefix + e + " (the answer is kept and saved as soon as it can be)"));
            Saver.Pump();
            return Error == null;
        }

        /// <summary>Every frame (main thread): delivers finished writes and retries a failed one. True when an answer was saved (the trial changed).</summary>
        public bool Update() => Saver.Pump() > 0;

        /// <summary>Waits up to <paramref name="timeoutMs"/> for the answer being written (a pause, quitting). True when nothing is left unsaved.</summary>
        public bool Flush(int timeoutMs = 5000) => Saver.Drain(timeoutMs);

        void Acknowledged(DiscriminationSession session)
        {
            session.Acknowledge();
            if (session != Session) return;
            Error = null;
            Saved?.Invoke();
        }

        /// <summary>The text the task shows: the error, waiting, done, or the trial's progress and what to do.</summary>
        public string DisplayText()
        {
            if (Error != null) return Error;
            if (Session == null) return WaitingText;
            if (Session.IsSaving) return "Trial " + Session.ProgressText + "\n" + SavingText;
            if (Session.IsFinished) return DoneText;
            string lifts = Session.CanAnswer ? AnswerText
                : LiftText + (Session.WasLifted(PairSide.Left) ? " (left: done)" : "") + (Session.WasLifted(PairSide.Right) ? " (right: done)" : "");
            return "Trial " + Session.ProgressText + "\n" + lifts;
        }

        bool Fail(string error)
        {
            Error = error;
            Failed?.Invoke(error);
            return false;
        }
    }
}
