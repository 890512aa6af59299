using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// One button of a <see cref="QuestionnairePanel"/>: a trigger box that a <see cref="FingertipPoker"/> pokes.
    /// It reports the fingertip's contacts to its panel, which decides (through its debounce) whether a contact
    /// is a poke. The panel creates these; they are not meant to be added by hand.
    /// </summary>
    [AddComponentMenu("")]
    public sealed class PokeButton : FingertipTrigger
    {
        QuestionnairePanel _panel;

        public PanelAction Kind { get; private set; }

        /// <summary>The point on the scale, for <see cref="PanelAction.Answer"/>.</summary>
        public int Value { get; internal set; }

        /// <summary>The button's face, m (local x and y); a point within it counts as on the button.</summary>
        public Vector2 Size { get; internal set; }

        public BoxCollider Collider { get; private set; }
        public Renderer Face { get; private set; }
        public TextMesh Label { get; private set; }

        internal void Initialize(QuestionnairePanel panel, PanelAction kind, BoxCollider collider, Renderer face, TextMesh label)
        {
            _panel = panel;
            Kind = kind;
            Collider = collider;
            Face = face;
            Label = label;
        }

        /// <summary>Whether <paramref name="world"/> lies within the button's face (its depth is not checked).</summary>
        public bool Contains(Vector3 world)
        {
            Vector3 local = transform.InverseTransformPoint(world);
            return local.x >= -Size.x / 2 && local.x <= Size.x / 2 && local.y >= -Size.y / 2 && local.y <= Size.y / 2;
        }

        protected override void Touched(double now)
        {
            if (_panel != null) _panel.Touch(this, now);
        }

        protected override void Stayed(double now)
        {
            if (_panel != null) _panel.Stay(now);
        }
    }
}
