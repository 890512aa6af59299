using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Turns a fingertip's contacts with a panel's buttons into pokes, so that one poke is one answer. A contact
    /// that begins counts as a poke only if the fingertip had touched no button for <see cref="ReleaseTime"/>
    /// (it was withdrawn, not sliding from one button onto the next or flickering at a button's edge) and
    /// the last poke is at least <see cref="Cooldown"/> old (a page that changes under a finger is not
    /// answered by that finger). Contacts are reported as they begin (<see cref="Touch"/>) and while they last
    /// (<see cref="Stay"/>), so a contact whose end is never reported (its button was hidden or destroyed)
    /// simply stops counting. Times in seconds on any clock that does not go back. Allocates nothing.
    /// </summary>
    public sealed class PokeDebounce
    {
        public const double DefaultCooldown = 0.5;
        public const double DefaultReleaseTime = 0.15;

        double lastPoke = double.NegativeInfinity;
        double lastContact = double.NegativeInfinity;

        /// <summary>Shortest time between two pokes, s.</summary>
        public double Cooldown { get; }

        /// <summary>How long the fingertip must have touched no button before a new contact is a poke, s.</summary>
        public double ReleaseTime { get; }

        public PokeDebounce(double cooldown = DefaultCooldown, double releaseTime = DefaultReleaseTime)
        {
            if (!(cooldown >= 0) || double.IsInfinity(cooldown)) throw new ArgumentOutOfRangeException(nameof(cooldown), "must be a finite number ≥ 0");
            if (!(releaseTime >= 0) || double.IsInfinity(releaseTime)) throw new ArgumentOutOfRangeException(nameof(releaseTime), "must be a finite number ≥ 0");
            Cooldown = cooldown;
            ReleaseTime = releaseTime;
        }

        /// <summary>A contact begins at <paramref name="now"/>; true when it is a poke.</summary>
        public bool Touch(double now)
        {
            bool poke = now - lastContact >= ReleaseTime && now - lastPoke >= Cooldown;
            if (now > lastContact) lastContact = now;
            if (poke) lastPoke = now;
            return poke;
        }

        /// <summary>A contact lasts at <paramref name="now"/>.</summary>
        public void Stay(double now)
        {
            if (now > lastContact) lastContact = now;
        }

        /// <summary>
        /// A poke that needs no contact tracking (the Interaction SDK's poke selects once per poke): true unless
        /// it comes within <see cref="Cooldown"/> of the last poke.
        /// </summary>
        public bool Press(double now)
        {
            if (now - lastPoke < Cooldown) return false;
            lastPoke = now;
            return true;
        }

        /// <summary>Forgets every contact and poke.</summary>
        public void Reset()
        {
            lastPoke = double.NegativeInfinity;
            lastContact = double.NegativeInfinity;
        }
    }
}
