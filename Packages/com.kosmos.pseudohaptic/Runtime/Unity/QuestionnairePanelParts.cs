using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The primitives a <see cref="QuestionnairePanel"/> is drawn with, built at run time from quads, cubes and 3D text
    /// (no UI package), and <see cref="Apply"/>, which writes a <see cref="PanelView"/> into them. Construction only: what
    /// is shown is decided by <see cref="QuestionnairePanelModel"/>, where the scale buttons go by its
    /// <see cref="QuestionnairePanelModel.ScaleLayout"/>.
    /// </summary>
    public sealed class QuestionnairePanelParts
    {
        /// <summary>Sizes (m), colours and words of the panel.</summary>
        public sealed class Style
        {
            public Vector2 Size = new Vector2(0.6f, 0.42f);
            public float TextSize = 0.004f;
            public Color Panel, Text, Button, Chosen, ButtonText;
            public string Back = "Back", Next = "Next";
        }

        const float Margin = QuestionnairePanelModel.Margin, ButtonHeight = QuestionnairePanelModel.ButtonHeight, RowY = QuestionnairePanelModel.ScaleRowY;

        readonly QuestionnairePanel _panel;
        readonly Transform _root;
        readonly Style _style;
        readonly Font _font;
        public readonly List<PokeButton> Scale = new List<PokeButton>();
        public readonly TextMesh Title, Progress, Instructions, Item, MinLabel, MaxLabel, Message;
        public readonly PokeButton Back, Next;

        public QuestionnairePanelParts(QuestionnairePanel panel, Style style)
        {
            _panel = panel;
            _root = panel.transform;
            _style = style;
            _font = Resources.GetBuiltinResource<Font>("LegacyRuntime.ttf"); // Unity 2022.2+ ships its legacy font under this name

            var background = GameObject.CreatePrimitive(PrimitiveType.Quad);
            background.name = "Background";
            background.GetComponent<Collider>().enabled = false;
            background.transform.SetParent(_root, false);
            background.transform.localPosition = new Vector3(0, 0, 0.006f);
            background.transform.localScale = new Vector3(style.Size.x, style.Size.y, 1);
            Tint(background.GetComponent<Renderer>(), style.Panel);

            float left = -style.Size.x / 2 + Margin, right = style.Size.x / 2 - Margin, top = style.Size.y / 2 - Margin;
            float small = style.TextSize * 0.75f, labelsY = RowY - ButtonHeight / 2 - 0.01f, bottom = -style.Size.y / 2 + Margin + 0.025f;
            Title = Text("Title", new Vector3(left, top, 0), TextAnchor.UpperLeft, TextAlignment.Left, style.TextSize * 0.85f, style.Text);
            Progress = Text("Progress", new Vector3(right, top, 0), TextAnchor.UpperRight, TextAlignment.Right, style.TextSize * 0.85f, style.Text);
            Instructions = Text("Instructions", new Vector3(left, top - 0.035f, 0), TextAnchor.UpperLeft, TextAlignment.Left, small, style.Text);
            Item = Text("Item", new Vector3(0, 0.07f, 0), TextAnchor.MiddleCenter, TextAlignment.Center, style.TextSize, style.Text);
            MinLabel = Text("Scale Min Label", new Vector3(left, labelsY, 0), TextAnchor.UpperLeft, TextAlignment.Left, small, style.Text);
            MaxLabel = Text("Scale Max Label", new Vector3(right, labelsY, 0), TextAnchor.UpperRight, TextAlignment.Right, small, style.Text);
            Message = Text("Message", new Vector3(0, bottom, 0), TextAnchor.MiddleCenter, TextAlignment.Center, small, style.Chosen);
            Back = Button("Back", PanelAction.Back, new Vector3(left + 0.06f, bottom, 0), new Vector2(0.12f, 0.05f), style.Back);
            Next = Button("Next", PanelAction.Next, new Vector3(right - 0.06f, bottom, 0), new Vector2(0.12f, 0.05f), style.Next);
        }

        /// <summary>Writes <paramref name="view"/> into the primitives, laying out (and making, if needed) its scale buttons.</summary>
        public void Apply(in PanelView view)
        {
            Title.text = view.Title;
            Progress.text = view.Progress;
            Instructions.text = view.Instructions;
            Item.text = view.Main;
            MinLabel.text = view.MinLabel;
            MaxLabel.text = view.MaxLabel;
            Message.text = view.Message;
            while (Scale.Count < view.Points) Scale.Add(Button("Answer " + (Scale.Count + 1), PanelAction.Answer, Vector3.zero, new Vector2(0.05f, ButtonHeight), ""));
            float edge = 0;
            for (int i = 0; i < Scale.Count; i++)
            {
                PokeButton b = Scale[i];
                SetActive(b, i < view.Points);
                float x = QuestionnairePanelModel.ScaleLayout(i, view.Points, _style.Size.x, out float width, out edge);
                b.transform.localPosition = new Vector3(x, RowY, 0);
                Resize(b, new Vector2(width, ButtonHeight));
                b.Value = view.ScaleMin + i;
                b.Label.text = QuestionnairePanelModel.Label(b.Value);
                Tint(b.Face, view.Chosen == b.Value ? _style.Chosen : _style.Button);
            }
            // The end labels sit under the first and last buttons.
            MinLabel.transform.localPosition = new Vector3(-edge, MinLabel.transform.localPosition.y, 0);
            MaxLabel.transform.localPosition = new Vector3(edge, MaxLabel.transform.localPosition.y, 0);
            SetActive(Back, view.CanBack);
            SetActive(Next, view.CanNext);
        }

        /// <summary>The active button whose face contains <paramref name="world"/>, or null.</summary>
        public PokeButton ButtonAt(Vector3 world)
        {
            for (int i = 0; i < Scale.Count; i++)
                if (Scale[i].gameObject.activeSelf && Scale[i].Contains(world)) return Scale[i];
            if (Back.gameObject.activeSelf && Back.Contains(world)) return Back;
            return Next.gameObject.activeSelf && Next.Contains(world) ? Next : null;
        }

        static void SetActive(PokeButton button, bool active)
        {
            if (button.gameObject.activeSelf != active) button.gameObject.SetActive(active);
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
            => Text(_root, objectName, localPosition + new Vector3(0, 0, -0.002f), anchor, alignment, characterSize, color);

        TextMesh Text(Transform parent, string objectName, Vector3 localPosition, TextAnchor anchor, TextAlignment alignment, float characterSize, Color color)
        {
            var go = new GameObject(objectName);
            go.transform.SetParent(parent, false);
            go.transform.localPosition = localPosition;
            var text = go.AddComponent<TextMesh>();
            text.anchor = anchor;
            text.alignment = alignment;
            text.fontSize = QuestionnairePanelModel.FontSize;
            text.characterSize = characterSize;
            text.color = color;
            if (_font == null) return text;
            text.font = _font;
            go.GetComponent<MeshRenderer>().sharedMaterial = _font.material;
            return text;
        }

        PokeButton Button(string objectName, PanelAction action, Vector3 localPosition, Vector2 size, string label)
        {
            var root = new GameObject(objectName);
            root.transform.SetParent(_root, false);
            root.transform.localPosition = localPosition;
            var collider = root.AddComponent<BoxCollider>();
            collider.isTrigger = true;

            var face = GameObject.CreatePrimitive(PrimitiveType.Cube);
            face.name = "Face";
            face.GetComponent<Collider>().enabled = false;
            face.transform.SetParent(root.transform, false);
            var renderer = face.GetComponent<Renderer>();
            Tint(renderer, _style.Button);

            TextMesh text = Text(root.transform, "Label", new Vector3(0, 0, -0.007f), TextAnchor.MiddleCenter, TextAlignment.Center, _style.TextSize * 0.9f, _style.ButtonText);
            text.text = label;
            var button = root.AddComponent<PokeButton>();
            button.Initialize(_panel, action, collider, renderer, text);
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
