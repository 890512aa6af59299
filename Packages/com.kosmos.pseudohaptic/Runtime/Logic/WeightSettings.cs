using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>Where an object's mass comes from.</summary>
    public enum MassSource
    {
        /// <summary>The Rigidbody's mass.</summary>
        Rigidbody,
        /// <summary>m = ρ·V with V the collider's volume (box, sphere, capsule or mesh); written to the Rigidbody if any.</summary>
        DensityTimesVolume,
        /// <summary>The mass given; written to the Rigidbody if any.</summary>
        Explicit,
    }

    /// <summary>Where the user's standard speed v_std comes from.</summary>
    public enum StandardSpeedSource
    {
        /// <summary>The current user's stored calibration, else the solver's default.</summary>
        UserCalibration,
        /// <summary>The speed given.</summary>
        Explicit,
    }

    /// <summary>What the Rigidbody gets back when the hold ends (paper 3.3 removes inertia while held; release is a setting).</summary>
    public enum ReleaseVelocity
    {
        Zero,
        /// <summary>The object's own velocity over its last motion.</summary>
        Object,
        /// <summary>The hand's velocity over its last motion (a throw).</summary>
        Hand,
    }

    /// <summary>Who makes the Rigidbody kinematic during a hold.</summary>
    public enum RigidbodyControl
    {
        /// <summary>The weight component: kinematic while held, falling velocity removed, release velocity per setting.</summary>
        ByThisComponent,
        /// <summary>The grab system (e.g. the Interaction SDK's Grabbable): the weight leaves the Rigidbody alone.</summary>
        External,
    }

    /// <summary>The volume of the object's collider, m³, or false with the reason (asked only when the mass needs it).</summary>
    public delegate bool VolumeQuery(out double volume, out string error);

    /// <summary>Which settings a component was last configured with, to know when to configure again (a setting, the profile asset or its version changed).</summary>
    public sealed class ConfigurationWatch
    {
        object _asset;
        int _version;
        bool _dirty = true;

        /// <summary>A setting changed.</summary>
        public void MarkDirty() => _dirty = true;

        /// <summary>Whether the configuration is out of date for this profile asset (null: none) at this version.</summary>
        public bool IsStale(object asset, int version) => _dirty || !ReferenceEquals(asset, _asset) || version != _version;

        /// <summary>Configured now with this asset at this version.</summary>
        public void Configured(object asset, int version)
        {
            _dirty = false;
            _asset = asset;
            _version = version;
        }
    }

    /// <summary>The decisions behind an object's weight settings: its mass, the user's speed, the release velocity.</summary>
    public static class WeightSettings
    {
        /// <summary>
        /// The weight model of an object's settings, or false with the reason (the core's message, naming the field).
        /// <paramref name="rigidbodyMass"/> is NaN when the object has no Rigidbody; <paramref name="volume"/> is
        /// asked only for <see cref="MassSource.DensityTimesVolume"/>.
        /// </summary>
        public static bool TryCreateModel(MassSource source, double rigidbodyMass, double density, double explicitMass,
                                          VolumeQuery volume, string objectName, out WeightModel model, out string error)
        {
            model = null;
            error = null;
            try
            {
                switch (source)
                {
                    case MassSource.Rigidbody:
                        if (double.IsNaN(rigidbodyMass)) { error = "Mass Source is Rigidbody, but there is no Rigidbody on '" + objectName + "'"; return false; }
                        model = WeightModel.FromMass(rigidbodyMass);
                        return true;
                    case MassSource.DensityTimesVolume:
                        if (volume == null) { error = "Mass Source is Density Times Volume, but there is no collider to take the volume from"; return false; }
                        if (!volume(out double v, out error)) return false;
                        model = WeightModel.FromDensity(density, v);
                        return true;
                    default:
                        model = WeightModel.FromMass(explicitMass);
                        return true;
                }
            }
            catch (ArgumentException e)
            {
                error = e.Message;
                return false;
            }
        }

        /// <summary>
        /// Configures <paramref name="hold"/> from an object's settings: its model (see <see cref="TryCreateModel"/>), its
        /// profile (null with <paramref name="profileError"/> when the asset is invalid) and the user's speed. False with
        /// the reason (naming the field), the hold keeping its last valid configuration. <paramref name="rigidbodyMassToWrite"/>
        /// is the mass to write back to the Rigidbody, NaN when nothing is to be written.
        /// </summary>
        public static bool TryConfigure(HeldObject hold, MassSource source, double rigidbodyMass, double density, double explicitMass,
                                        VolumeQuery volume, string objectName, WeightProfile profile, string profileError, double standardSpeed,
                                        out double rigidbodyMassToWrite, out string error, double cueStrength = WeightSolver.DefaultCueStrength)
        {
            rigidbodyMassToWrite = double.NaN;
            error = profileError ?? (profile == null ? "no profile" : null);
            if (error != null || !TryCreateModel(source, rigidbodyMass, density, explicitMass, volume, objectName, out WeightModel model, out error)) return false;
            if (!hold.Configure(model, profile, standardSpeed, cueStrength)) { error = hold.Error; return false; }
            if (WritesRigidbodyMass(source) && !double.IsNaN(rigidbodyMass)) rigidbodyMassToWrite = model.MassKg;
            return true;
        }

        /// <summary>
        /// Null when an object whose mass a task sets each trial (through its explicit mass) takes its mass from there;
        /// otherwise why it cannot be used: with any other source the trial's mass would never reach the solver.
        /// </summary>
        public static string ExplicitMassError(string objectRole, MassSource source) => source == MassSource.Explicit ? null
            : "the " + objectRole + " object's Mass Source is " + source + ", but the task sets each trial's mass through Explicit Mass Kg: set its Mass Source to Explicit";

        /// <summary>Whether the resolved mass is written back to the Rigidbody (it came from elsewhere).</summary>
        public static bool WritesRigidbodyMass(MassSource source) => source != MassSource.Rigidbody;

        /// <summary>The user's v_std, m/s: the explicit one, or the stored calibration's.</summary>
        public static double StandardSpeed(StandardSpeedSource source, double explicitSpeed, double storedOrDefault) =>
            source == StandardSpeedSource.Explicit ? explicitSpeed : storedOrDefault;

        /// <summary>The cue strength an object applies (issue 31): the user's stored one when <paramref name="fromUser"/>, else 1.</summary>
        public static double CueStrength(bool fromUser, double stored) => fromUser ? stored : WeightSolver.DefaultCueStrength;

        /// <summary>The velocity a released body gets, world space, m/s.</summary>
        public static Vector3d Release(ReleaseVelocity kind, Vector3d hand, Vector3d obj) =>
            kind == ReleaseVelocity.Hand ? hand : kind == ReleaseVelocity.Object ? obj : Vector3d.Zero;
    }
}
