using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// From this object's settings (the serialized fields, in PseudoHapticWeight.cs) to its solver's configuration:
    /// the mass model (and a mesh collider's volume stored in the editor), the profile, the user's standard speed and
    /// cue strength, and when to configure again (a setting, the profile asset or the user's calibration changed:
    /// <see cref="ConfigurationWatch"/>). The decisions are <see cref="WeightSettings"/>'s; this reads the Rigidbody,
    /// the collider and the stores, and logs a configuration that cannot be used.
    /// </summary>
    public sealed partial class PseudoHapticWeight
    {
        readonly ConfigurationWatch _watch = new ConfigurationWatch();
        string _error;

        public string ConfigurationError => _error;

        /// <summary>Whether the user's stored cue strength applies (else 1).</summary>
        public bool UserCueStrength { get => _userCueStrength; set { _userCueStrength = value; _watch.MarkDirty(); } }
        public Collider VolumeCollider { get => _volumeCollider; set { _volumeCollider = value; _watch.MarkDirty(); } }
        public PseudoHapticProfile Profile { get => _profile; set { _profile = value; _watch.MarkDirty(); } }
        public MassSource Mass { get => _massSource; set { _massSource = value; _watch.MarkDirty(); } }
        public float ExplicitMassKg { get => _explicitMassKg; set { _explicitMassKg = value; _watch.MarkDirty(); } }
        public float DensityKgPerCubicMetre { get => _densityKgPerCubicMetre; set { _densityKgPerCubicMetre = value; _watch.MarkDirty(); } }
        public StandardSpeedSource SpeedSource { get => _standardSpeedSource; set { _standardSpeedSource = value; _watch.MarkDirty(); } }
        public float ExplicitStandardSpeed { get => _explicitStandardSpeed; set { _explicitStandardSpeed = value; _watch.MarkDirty(); } }

        bool NeedsConfiguration => _watch.IsStale(_profile != null ? _profile : null, _profile != null ? _profile.Version : 0);
        void MarkDirty() => _watch.MarkDirty();

        void OnValidate()
        {
            _watch.MarkDirty();
#if UNITY_EDITOR
            if (_massSource == MassSource.DensityTimesVolume) StoreMeshVolume();
#endif
        }

        /// <summary>Stores the mesh collider's volume with the component (read in the editor), so a player build that strips the mesh needs none. Allocates.</summary>
        public bool StoreMeshVolume()
        {
            if (!ColliderVolume.TryReadMesh(Collider, out Mesh mesh, out double volume)) return false; // keeps what was stored
            _storedVolumeMesh = mesh;
            _storedMeshVolume = volume;
            _watch.MarkDirty();
            return true;
        }

        /// <summary>The weight model of this object's settings, or false with the reason. Reading a mesh's volume allocates.</summary>
        public bool TryCreateModel(out WeightModel model, out string error) =>
            WeightSettings.TryCreateModel(_massSource, Body != null ? Body.mass : double.NaN, _densityKgPerCubicMetre, _explicitMassKg, Volume, name, out model, out error);

        bool Volume(out double volume, out string error) => ColliderVolume.TryGet(Collider, _storedVolumeMesh, _storedMeshVolume, out volume, out error);

        /// <summary>The profile this object uses: its asset's, or the "paper" preset.</summary>
        public bool TryGetProfile(out WeightProfile profile, out string error)
        {
            error = null;
            profile = NamedProfiles.Paper;
            return _profile == null || _profile.TryBuild(out profile, out error);
        }

        public double ResolveStandardSpeed() =>
            WeightSettings.StandardSpeed(_standardSpeedSource, _explicitStandardSpeed, UserCalibrationStore.StandardSpeedOrDefault);

        /// <summary>The cue strength this object applies: the user's stored one, or 1.</summary>
        public double ResolveCueStrength() => WeightSettings.CueStrength(_userCueStrength, UserCalibrationStore.CueStrengthOrDefault);

        /// <summary>Applies the settings to the solver (also during a hold); on invalid ones logs the reason, keeps the last valid configuration, returns false.</summary>
        public bool Configure()
        {
            _watch.Configured(_profile != null ? _profile : null, _profile != null ? _profile.Version : 0);
            TryGetProfile(out WeightProfile profile, out string profileError);
            bool ok = WeightSettings.TryConfigure(Hold, _massSource, Body != null ? Body.mass : double.NaN, _densityKgPerCubicMetre, _explicitMassKg,
                                                  Volume, name, profile, profileError, ResolveStandardSpeed(), out double write, out _error, ResolveCueStrength());
            if (!ok) Debug.LogError("Pseudo-haptic weight on '" + name + "' is not configured: " + _error, this);
            if (!double.IsNaN(write)) Body.mass = (float)write;
            return ok;
        }
    }
}
