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

        /// <summary>The session; null before a successful <see cref="Begin"/>.</summary>
        public DiscriminationSession Session { get; private set; }
        /// <summary>Why the task cannot run or the last answer was not saved; null when all is well.</summary>
        public string Error { get; private set; }
        public PokeDebounce Debounce { get; }
        /// <summary>True when a trial is under way (its masses are to be on the objects).</summary>
        public bool HasTrial => Session != null && !Session.IsFinished;

        /// <summary>Raised with the message when something fails.</summary>
        public event Action<string> Failed;

        public DiscriminationTaskModel(double cooldown = PokeDebounce.DefaultCooldown, double releaseTime = PokeDebounce.DefaultReleaseTime)
            => Debounce = new PokeDebounce(cooldown, releaseTime);

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
        /// Answers "the object on <paramref name="heavier"/> was heavier". True when the answer was saved; false
        /// when no answer is taken now, while an object is held (both must be put down first), or when the file
        /// could not be written (then with <see cref="Error"/>).
        /// </summary>
        public bool Answer(PairSide heavier, bool anyHeld)
        {
            if (Session == null || !Session.CanAnswer || anyHeld) return false;
            try
            {
                Session.Answer(heavier);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return Fail("the answer could not be saved: " + e.Message);
            }
            Error = null;
            return true;
        }

        /// <summary>The text the task shows: the error, waiting, done, or the trial's progress and what to do.</summary>
        public string DisplayText()
        {
            if (Error != null) return Error;
            if (Session == null) return WaitingText;
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
