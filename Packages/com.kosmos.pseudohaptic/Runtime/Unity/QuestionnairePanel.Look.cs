using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The panel's look: its size and text size (checked when set in code; serialized ones that are not positive
    /// lengths are reported and the defaults used), the primitives built with them (<see cref="QuestionnairePanelParts"/>),
    /// what they show now (read back by tests and tools), and the model's view written into them (<see cref="Show"/>).
    /// </summary>
    public sealed partial class QuestionnairePanel
    {
        QuestionnairePanelParts _parts;

        public IReadOnlyList<PokeButton> ScaleButtons => Parts.Scale;
        public PokeButton BackButton => Parts.Back;
        public PokeButton NextButton => Parts.Next;
        public string TitleText => Parts.Title.text;
        public string ProgressText => Parts.Progress.text;
        public string ItemText => Parts.Item.text;
        public string MinLabelText => Parts.MinLabel.text;
        public string MaxLabelText => Parts.MaxLabel.text;
        public string MessageText => Parts.Message.text;
        QuestionnairePanelParts Parts => _parts ?? (_parts = new QuestionnairePanelParts(this, new QuestionnairePanelParts.Style
        {
            Size = LookError == null ? _size : DefaultSize, TextSize = LookError == null ? _textSize : DefaultTextSize, Panel = _panelColor, Text = _textColor, Button = _buttonColor, Chosen = _chosenColor,
            ButtonText = _buttonTextColor, Back = _backText, Next = _nextText,
        }));

        /// <summary>Width and height of the panel, m (each finite, &gt; 0); set before the panel is first shown.</summary>
        public Vector2 Size
        {
            get => _size;
            set
            {
                FieldRules.Require(FieldRules.First(FieldRules.Positive("Size.x", value.x), FieldRules.Positive("Size.y", value.y)), nameof(Size), value.x);
                _size = value;
            }
        }

        /// <summary>Character size of the item text (finite, &gt; 0); set before the panel is first shown.</summary>
        public float TextSize
        {
            get => _textSize;
            set
            {
                FieldRules.Require(FieldRules.Positive(nameof(TextSize), value), nameof(TextSize), value);
                _textSize = value;
            }
        }

        /// <summary>Why the panel's look cannot be built (a size or text size that is not a positive length), or null.</summary>
        public string LookError => FieldRules.First(FieldRules.Positive("Size.x", _size.x), FieldRules.Positive("Size.y", _size.y), FieldRules.Positive("Text Size", _textSize));

        void Awake()
        {
            if (LookError != null) Debug.LogError("Questionnaire panel '" + name + "': " + LookError + "; the defaults are used", this);
        }

        void OnValidate()
        {
            if (LookError != null) Debug.LogError("Questionnaire panel '" + name + "': " + LookError, this);
        }

        /// <summary>Shows the model's current view.</summary>
        public void Show() => Parts.Apply(LookError == null ? Model.View(_size.x, _textSize) : Model.View(DefaultSize.x, DefaultTextSize));

        static readonly Vector2 DefaultSize = new Vector2(0.6f, 0.42f);
        const float DefaultTextSize = 0.004f;
    }
}
