using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.SampleScenes
{
    /// <summary>
    /// Builds Experiment 1 of Son et al. 2022 (§4.1) when the scene starts: boxes A, B and C of the same size and
    /// different densities (B heaviest) on a table, under the "paper-experiment" profile (no offset correction,
    /// as the experiment ran). Put it on an empty GameObject in a scene that has a hand rig.
    /// </summary>
    public sealed class Experiment1Setup : MonoBehaviour
    {
        [Tooltip("The boxes' profile; the paper-experiment preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile = null;

        void Awake()
        {
            SampleContent.HandsInScene("Experiment 1 sample", this);
            PseudoHapticProfile profile = _profile != null ? _profile : PseudoHapticProfile.CreatePreset(NamedProfiles.PaperExperimentName);
            SampleContent.Experiment1(transform, profile);
        }
    }
}
