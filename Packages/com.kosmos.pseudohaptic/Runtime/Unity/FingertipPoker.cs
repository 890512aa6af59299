using System;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A small trigger sphere on the index fingertip that pokes the buttons of a <see cref="QuestionnairePanel"/>,
    /// for scenes without the Interaction SDK's poke. Put it on the fingertip bone itself; or anywhere, with
    /// <see cref="Follow"/> set to the bone; or with <see cref="FindUnder"/> set to the hand (e.g. the
    /// <c>OVRHandPrefab</c>, whose skeleton creates its bones at run time), where it looks for a bone whose name
    /// ends in "IndexTip" (<c>Hand_IndexTip</c>, <c>XRHand_IndexTip</c>) and follows it once found. It adds its own
    /// <see cref="SphereCollider"/> (a trigger) and kinematic <see cref="Rigidbody"/>, which Unity needs to report
    /// trigger contacts. While the optional hand source reports no tracking, the collider is off, so a lost hand
    /// pokes nothing. The debounce that makes one poke one answer is the panel's.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Fingertip Poker")]
    public sealed class FingertipPoker : MonoBehaviour
    {
        [Tooltip("The index fingertip to follow; empty: this object is the fingertip, or one is looked for under Find Under.")]
        [SerializeField] Transform _follow;
        [Tooltip("Where to look for the fingertip bone while Follow is empty, e.g. the hand prefab (its bones may appear only at run time).")]
        [SerializeField] Transform _findUnder;
        [Tooltip("The fingertip bone's name ends with this (any case).")]
        [SerializeField] string _boneNameEnding = "IndexTip";
        [Tooltip("An IHandPoseSource whose tracking switches the poker on and off. Optional.")]
        [SerializeField] MonoBehaviour _hand;
        [Tooltip("Radius of the fingertip sphere, m.")]
        [SerializeField] float _radius = 0.008f;

        const double SearchInterval = 0.5;

        IHandPoseSource _source;
        SphereCollider _collider;
        double _nextSearch;

        public IHandPoseSource Hand => _source ?? (_source = HandSourceField.Resolve<IHandPoseSource>(_hand));

        public SphereCollider Collider => _collider;

        /// <summary>Radius of the fingertip sphere, m (finite, &gt; 0).</summary>
        public float Radius
        {
            get => _radius;
            set
            {
                FieldRules.Require(FieldRules.Positive(nameof(Radius), value), nameof(Radius), value);
                _radius = value;
                if (_collider != null) _collider.radius = value;
            }
        }

        /// <summary>The fingertip followed; null when this object is the fingertip (or none is found yet).</summary>
        public Transform Follow
        {
            get => _follow;
            set => _follow = value;
        }

        /// <summary>Where the fingertip bone is looked for while <see cref="Follow"/> is empty.</summary>
        public Transform FindUnder
        {
            get => _findUnder;
            set { _findUnder = value; _nextSearch = 0; }
        }

        /// <summary>Sets the hand in code (tests, scene builders).</summary>
        public void InjectHand(IHandPoseSource hand)
        {
            _source = hand;
            _hand = hand as MonoBehaviour;
        }

        void OnValidate()
        {
            MonoBehaviour source = HandSourceField.Normalize<IHandPoseSource>(_hand);
            if (source != null) _hand = source;
            _source = null;
        }

        void Awake()
        {
            _collider = GetComponent<SphereCollider>();
            if (_collider == null) _collider = gameObject.AddComponent<SphereCollider>();
            _collider.isTrigger = true;
            string radius = FieldRules.Positive("Radius", _radius);
            if (radius != null)
            {
                Debug.LogError("Fingertip Poker on '" + name + "': " + radius + "; it keeps the collider's radius " + _collider.radius, this);
                _radius = _collider.radius;
            }
            _collider.radius = _radius;
            var body = GetComponent<Rigidbody>();
            if (body == null) body = gameObject.AddComponent<Rigidbody>();
            body.isKinematic = true;
        }

        void Update() => Tick();

        /// <summary>Follows the fingertip and switches the collider with tracking; Update calls it.</summary>
        public void Tick()
        {
            IHandPoseSource hand = Hand;
            bool tracked = hand == null || hand.IsTracked;
            if (_collider != null && _collider.enabled != tracked) _collider.enabled = tracked;

            if (_follow == null && _findUnder != null && Time.unscaledTimeAsDouble >= _nextSearch)
            {
                _nextSearch = Time.unscaledTimeAsDouble + SearchInterval;
                _follow = FindBone(_findUnder, _boneNameEnding);
            }
            if (tracked && _follow != null) transform.position = _follow.position;
        }

        /// <summary>
        /// The first transform under <paramref name="root"/>, depth first, whose name ends with
        /// <paramref name="ending"/> (any case), skipping bind-pose copies (a subtree named "BindPoses"); null if none.
        /// </summary>
        public static Transform FindBone(Transform root, string ending)
        {
            if (root == null || string.IsNullOrEmpty(ending)) return null;
            string name = root.name;
            if (name.EndsWith(ending, StringComparison.OrdinalIgnoreCase)) return root;
            if (name == "BindPoses") return null;
            for (int i = 0; i < root.childCount; i++)
            {
                Transform found = FindBone(root.GetChild(i), ending);
                if (found != null) return found;
            }
            return null;
        }
    }
}
