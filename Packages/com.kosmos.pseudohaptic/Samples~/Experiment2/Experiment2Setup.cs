using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.SampleScenes
{
    /// <summary>
    /// Builds Experiment 2 of Son et al. 2022 (§4.2) when the scene starts: water bottles from 0.33 L to 2 L on a
    /// table, each a cylinder mesh collider whose mass is water's density times the mesh's volume, under the
    /// "paper-experiment" profile. Put it on an empty GameObject in a scene that has a hand rig.
    /// </summary>
    public sealed class Experiment2Setup : MonoBehaviour
    {
        [Tooltip("The bottles' profile; the paper-experiment preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile = null;

        void Awake()
        {
            SampleContent.HandsInScene("Experiment 2 sample", this);
            PseudoHapticProfile profile = _profile != null ? _profile : PseudoHapticProfile.CreatePreset(NamedProfiles.PaperExperimentName);
            SampleContent.Experiment2(transform, profile);
        }
    }
}
