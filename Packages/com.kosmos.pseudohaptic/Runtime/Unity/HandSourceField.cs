using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Unity serializes no interface fields, so components keep their hand source as a MonoBehaviour and
    /// read it through this: the behaviour itself when it implements T, else another component on its GameObject.
    /// </summary>
    public static class HandSourceField
    {
        public static T Resolve<T>(MonoBehaviour behaviour) where T : class
        {
            if (behaviour == null) return null;
            if (behaviour is T direct) return direct;
            T found = behaviour.GetComponent<T>();
            // In the editor a missing component comes back as a "fake null" object: treat it as none.
            return found is Object o && o == null ? null : found;
        }

        /// <summary>For OnValidate: the component on the same GameObject that implements T, or null.</summary>
        public static MonoBehaviour Normalize<T>(MonoBehaviour behaviour) where T : class
            => Resolve<T>(behaviour) as MonoBehaviour;
    }
}
