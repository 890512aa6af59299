using Oculus.Interaction;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Interaction
{
    /// <summary>
    /// Lets Meta's Interaction SDK poke answer a <see cref="QuestionnairePanel"/>: give the panel one
    /// <c>PokeInteractable</c> whose surface covers the panel's face (a <c>PlaneSurface</c> at the panel, facing
    /// the participant, clipped to the panel's size), and put this component beside it. Each poke that selects
    /// the surface (<see cref="PointerEventType.Select"/>) presses the panel's button under the touch point
    /// (<see cref="PointerEvent.Pose"/>); the panel's cooldown keeps one poke one answer, also when a
    /// <see cref="FingertipPoker"/> touches the same button. The panel's buttons may change between pages;
    /// the one surface does not. Compiled only when com.meta.xr.sdk.interaction is installed.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Questionnaire Poke Surface (Interaction SDK)")]
    public sealed class QuestionnairePokeSurface : MonoBehaviour
    {
        [Tooltip("The panel to answer; found on this GameObject or its parents when empty.")]
        [SerializeField] QuestionnairePanel _panel;
        [Tooltip("The PokeInteractable (any IPointable) covering the panel; found on this GameObject when empty.")]
        [SerializeField] MonoBehaviour _pointable;

        IPointable _source;

        public QuestionnairePanel Panel => _panel;

        public void InjectPanel(QuestionnairePanel panel) => _panel = panel;

        public void InjectPointable(MonoBehaviour pointable)
        {
            Unsubscribe();
            _pointable = pointable;
            if (isActiveAndEnabled) Subscribe();
        }

        void Awake()
        {
            if (_panel == null) _panel = GetComponentInParent<QuestionnairePanel>();
        }

        void Start()
        {
            if (_source == null)
                Debug.LogError("Questionnaire Poke Surface on '" + name + "' found no IPointable (PokeInteractable) to listen to.", this);
        }

        void OnEnable() => Subscribe();

        void OnDisable() => Unsubscribe();

        void Subscribe()
        {
            _source = HandSourceField.Resolve<IPointable>(_pointable != null ? _pointable : this);
            if (_source != null) _source.WhenPointerEventRaised += HandlePointerEvent;
        }

        void Unsubscribe()
        {
            if (_source != null) _source.WhenPointerEventRaised -= HandlePointerEvent;
            _source = null;
        }

        void HandlePointerEvent(PointerEvent evt)
        {
            if (evt.Type != PointerEventType.Select || _panel == null) return;
            _panel.PokeAt(evt.Pose.position, Time.unscaledTimeAsDouble);
        }
    }
}
