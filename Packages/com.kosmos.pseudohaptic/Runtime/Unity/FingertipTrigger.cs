using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A trigger box that a <see cref="FingertipPoker"/> pokes (the buttons of the questionnaire panel and of the
    /// discrimination task): it passes a fingertip's contact beginning and lasting, with the time, to the
    /// component that decides whether it is a poke. Other colliders are ignored. Whether a collider is a fingertip is
    /// decided once, when its contact begins (<see cref="ContactSet"/>); a lasting contact searches no component.
    /// </summary>
    public abstract class FingertipTrigger : MonoBehaviour
    {
        readonly ContactSet _fingertips = new ContactSet();

        /// <summary>A fingertip's contact begins at <paramref name="now"/> (Time.unscaledTimeAsDouble).</summary>
        protected abstract void Touched(double now);

        /// <summary>A fingertip's contact lasts at <paramref name="now"/>.</summary>
        protected abstract void Stayed(double now);

        protected void OnTriggerEnter(Collider other)
        {
            if (other.GetComponent<FingertipPoker>() == null) return;
            _fingertips.Add(other.GetInstanceID());
            Touched(Time.unscaledTimeAsDouble);
        }

        protected void OnTriggerStay(Collider other)
        {
            if (_fingertips.Contains(other.GetInstanceID())) Stayed(Time.unscaledTimeAsDouble);
        }

        protected void OnTriggerExit(Collider other) => _fingertips.Remove(other.GetInstanceID());

        protected void OnDisable() => _fingertips.Clear(); // Unity sends no exit to a disabled trigger's contacts
    }
}
