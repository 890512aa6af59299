// Test double of UnityEngine.Transform with Unity's documented semantics: a local position, rotation and scale under a
// parent; world values derived through the parent chain (TransformPoint applies scale, then rotation, then translation,
// level by level); setting a world value solves for the local one; SetParent(parent, true) keeps the world position,
// rotation and (as far as a non-uniform parent allows) scale. Public members are those of UnityCsReference 2022.3
// Runtime/Transform/ScriptBindings/Transform.bindings.cs that the package or the double uses.
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public class Transform : Component
    {
        Vector3 _localPosition;
        Quaternion _localRotation = Quaternion.identity;
        Vector3 _localScale = Vector3.one;
        Transform _parent;
        readonly List<Transform> _children = new List<Transform>();

        public Vector3 localPosition { get => _localPosition; set => _localPosition = value; }
        public Quaternion localRotation { get => _localRotation; set => _localRotation = value; }
        public Vector3 localScale { get => _localScale; set => _localScale = value; }

        public Vector3 position
        {
            get => _parent == null ? _localPosition : _parent.TransformPoint(_localPosition);
            set => _localPosition = _parent == null ? value : _parent.InverseTransformPoint(value);
        }

        public Quaternion rotation
        {
            get => _parent == null ? _localRotation : _parent.rotation * _localRotation;
            set => _localRotation = _parent == null ? value : Quaternion.Inverse(_parent.rotation) * value;
        }

        public Vector3 eulerAngles { get => rotation.eulerAngles; set => rotation = Quaternion.Euler(value); }

        /// <summary>The world scale, approximate under rotated non-uniform parents (as Unity's).</summary>
        public Vector3 lossyScale => _parent == null ? _localScale : Vector3.Scale(_parent.lossyScale, _localScale);

        public Vector3 forward => rotation * Vector3.forward;
        public Vector3 up => rotation * Vector3.up;
        public Vector3 right => rotation * Vector3.right;

        public Transform parent { get => _parent; set => SetParent(value, true); }
        public Transform root => _parent == null ? this : _parent.root;
        public int childCount => _children.Count;
        public Transform GetChild(int index) => _children[index];

        public void SetParent(Transform parent) => SetParent(parent, true);

        public void SetParent(Transform parent, bool worldPositionStays)
        {
            if (ReferenceEquals(parent, _parent)) return;
            for (Transform p = parent; p != null; p = p._parent)
                if (ReferenceEquals(p, this)) throw new InvalidOperationException("Cannot make '" + name + "' a child of its own child.");
            Vector3 worldPosition = position, worldScale = lossyScale;
            Quaternion worldRotation = rotation;
            Engine.ChangeActive(gameObject, () =>
            {
                _parent?._children.Remove(this);
                _parent = parent;
                _parent?._children.Add(this);
                Engine.ParentChanged(this);
            });
            if (!worldPositionStays) return;
            rotation = worldRotation;
            position = worldPosition;
            Vector3 parentScale = parent != null ? parent.lossyScale : Vector3.one;
            _localScale = new Vector3(Divide(worldScale.x, parentScale.x), Divide(worldScale.y, parentScale.y), Divide(worldScale.z, parentScale.z));
        }

        static float Divide(float a, float b) => b != 0 ? a / b : a;

        internal void DetachForDestroy()
        {
            _parent?._children.Remove(this);
            _parent = null;
        }

        internal IReadOnlyList<Transform> Children => _children;

        /// <summary>Local → parent → … → world.</summary>
        public Vector3 TransformPoint(Vector3 position)
        {
            Vector3 p = _localRotation * Vector3.Scale(_localScale, position) + _localPosition;
            return _parent == null ? p : _parent.TransformPoint(p);
        }

        public Vector3 TransformPoint(float x, float y, float z) => TransformPoint(new Vector3(x, y, z));

        public Vector3 InverseTransformPoint(Vector3 position)
        {
            Vector3 p = _parent == null ? position : _parent.InverseTransformPoint(position);
            Vector3 q = Quaternion.Inverse(_localRotation) * (p - _localPosition);
            return new Vector3(Divide(q.x, _localScale.x), Divide(q.y, _localScale.y), Divide(q.z, _localScale.z));
        }

        /// <summary>Rotation only, as Unity's TransformDirection.</summary>
        public Vector3 TransformDirection(Vector3 direction) => rotation * direction;
        public Vector3 InverseTransformDirection(Vector3 direction) => Quaternion.Inverse(rotation) * direction;

        /// <summary>A child by name, or a path of names separated by '/'.</summary>
        public Transform Find(string n)
        {
            Transform at = this;
            foreach (string part in n.Split('/'))
            {
                Transform next = null;
                foreach (Transform c in at._children)
                    if (c.gameObject.name == part) { next = c; break; }
                if (next == null) return null;
                at = next;
            }
            return at;
        }
    }
}
