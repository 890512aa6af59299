using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.SampleScenes
{
    /// <summary>
    /// Builds Experiment 1 of Son et al. 2022 (§6) when the scene starts: boxes A, B and C of the same size and
    /// different densities (B heaviest; PaperExperiment1) on a table, under the "paper-experiment" profile (no offset
    /// correction, both hands sharing the weight, as the experiment ran). Put it on an empty GameObject in a scene that
    /// has a hand rig (Meta's stock OVRCameraRig with OVRHandPrefabs will do).
    /// </summary>
    public sealed class Experiment1Setup : MonoBehaviour
    {
        [Tooltip("The boxes' profile; the paper-experiment preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile = null;

        void Awake()
        {
            SampleContent.HandsInScene("Experiment 1 sample", this);
            PseudoHapticProfile profile = _profile != null ? _profile : PseudoHapticProfile.CreatePreset(PaperExperiment1.ProfileName);
            SampleContent.Experiment1(transform, profile);
        }
    }
}
