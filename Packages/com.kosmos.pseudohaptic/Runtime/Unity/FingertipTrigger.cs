using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A trigger box that a <see cref="FingertipPoker"/> pokes (the buttons of the questionnaire panel and of the
    /// discrimination task): it passes a fingertip's contact beginning and lasting, with the time, to the
    /// component that decides whether it is a poke. Other colliders are ignored.
    /// </summary>
    public abstract class FingertipTrigger : MonoBehaviour
    {
        /// <summary>A fingertip's contact begins at <paramref name="now"/> (Time.timeAsDouble).</summary>
        protected abstract void Touched(double now);

        /// <summary>A fingertip's contact lasts at <paramref name="now"/>.</summary>
        protected abstract void Stayed(double now);

        protected void OnTriggerEnter(Collider other)
        {
            if (other.GetComponent<FingertipPoker>() != null) Touched(Time.timeAsDouble);
        }

        protected void OnTriggerStay(Collider other)
        {
            if (other.GetComponent<FingertipPoker>() != null) Stayed(Time.timeAsDouble);
        }
    }
}
