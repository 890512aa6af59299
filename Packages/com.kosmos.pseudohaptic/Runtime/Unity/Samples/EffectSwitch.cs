using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Samples
{
    /// <summary>
    /// A playground button that switches one effect of a profile asset on or off when a hand touches it
    /// (enters its radius). Every object using the profile picks the change up on its next frame.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Samples/Effect Switch")]
    public sealed class EffectSwitch : MonoBehaviour
    {
        [SerializeField] PseudoHapticProfile _profile;
        [Tooltip("The core's name of the effect, e.g. weight-gain (PseudoHapticProfile.EffectNames).")]
        [SerializeField] string _effect;
        [Tooltip("IHandPoseSource behaviours that can press the switch.")]
        [SerializeField] MonoBehaviour[] _hands = new MonoBehaviour[0];
        [SerializeField] float _radius = 0.04f;
        [SerializeField] TextMesh _label;

        IHandPoseSource[] _sources = new IHandPoseSource[0];
        bool[] _inside = new bool[0];

        public string Effect => _effect;

        /// <summary>How near a tracked hand must come to press the switch, m (finite, &gt; 0).</summary>
        public float Radius
        {
            get => _radius;
            set
            {
                FieldRules.Require(FieldRules.Positive(nameof(Radius), value), nameof(Radius), value);
                _radius = value;
            }
        }

        /// <summary>Why this switch cannot work (an effect the profile does not list, a bad radius), or null.</summary>
        public string ConfigurationError => !PseudoHapticProfile.IsKnownEffect(_effect)
            ? "effect '" + _effect + "' is unknown; known: " + string.Join(", ", PseudoHapticProfile.EffectNames)
            : FieldRules.Positive("Radius", _radius);

        public static EffectSwitch Create(Transform parent, string effect, Vector3 localPosition, PseudoHapticProfile profile, IReadOnlyList<IHandPoseSource> hands)
        {
            var button = GameObject.CreatePrimitive(PrimitiveType.Cube);
            button.name = "Switch " + effect;
            Object.DestroyImmediate(button.GetComponent<Collider>());
            button.transform.SetParent(parent, false);
            button.transform.localPosition = localPosition + new Vector3(0, 0.01f, 0);
            button.transform.localScale = new Vector3(0.05f, 0.02f, 0.05f);

            var label = SampleContent.Label(parent, effect, localPosition + new Vector3(0, 0.06f, 0));
            label.characterSize = 0.006f;

            // Inactive while its fields are set, so its Awake sees them (AddComponent on an active object runs Awake at once).
            button.SetActive(false);
            var s = button.AddComponent<EffectSwitch>();
            s._profile = profile;
            s._effect = effect;
            s._label = label;
            int n = hands != null ? hands.Count : 0;
            s._hands = new MonoBehaviour[n];
            for (int i = 0; i < n; i++) s._hands[i] = hands[i] as MonoBehaviour;
            button.SetActive(true);
            s.ShowState(); // also when the scene is built in the editor, where Start does not run
            return s;
        }

        void Awake()
        {
            ResolveHands();
            Validate();
        }

        void OnValidate()
        {
            if (ConfigurationError != null) Debug.LogError("Effect Switch on '" + name + "': " + ConfigurationError, this);
        }

        /// <summary>A switch that cannot work says why, once, and stays off (it would otherwise throw every frame).</summary>
        void Validate()
        {
            string error = ConfigurationError;
            if (error == null) return;
            Debug.LogError("Effect Switch on '" + name + "': " + error, this);
            enabled = false;
        }

        void ResolveHands()
        {
            _sources = new IHandPoseSource[_hands.Length];
            _inside = new bool[_hands.Length];
            for (int i = 0; i < _hands.Length; i++) _sources[i] = HandSourceField.Resolve<IHandPoseSource>(_hands[i]);
        }

        void Start() => ShowState();

        void Update()
        {
            if (_profile == null) return;
            Vector3 centre = transform.position;
            float r2 = _radius * _radius;
            for (int i = 0; i < _sources.Length; i++)
            {
                IHandPoseSource hand = _sources[i];
                bool inside = hand != null && hand.IsTracked && (hand.Position - centre).sqrMagnitude <= r2;
                if (inside && !_inside[i]) Toggle();
                _inside[i] = inside;
            }
        }

        /// <summary>Flips the effect and shows its new state.</summary>
        public void Toggle()
        {
            if (_profile == null || ConfigurationError != null) return;
            _profile.SetEnabled(_effect, !_profile.IsEnabled(_effect));
            ShowState();
        }

        void ShowState()
        {
            if (_label == null || _profile == null || !PseudoHapticProfile.IsKnownEffect(_effect)) return;
            _label.text = _effect + (_profile.IsEnabled(_effect) ? "\non" : "\noff");
        }
    }
}
