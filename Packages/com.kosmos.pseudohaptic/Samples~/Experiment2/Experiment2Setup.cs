using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.SampleScenes
{
    /// <summary>
    /// Builds Experiment 2 of Son et al. 2022 (§7) when the scene starts: water bottles from 0.33 L to 2 L on a
    /// table, each a cylinder mesh collider whose mass is water's density times the mesh's volume, under the
    /// "paper-experiment" profile. Put it on an empty GameObject in a scene that has a hand rig.
    /// </summary>
    public sealed class Experiment2Setup : MonoBehaviour
    {
        [Tooltip("The bottles' profile, used as it is (with Two Hands off each hand lifts the whole bottle; the setup says so); the paper-experiment preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile = null;

        void Awake()
        {
            SampleContent.HandsInScene("Experiment 2 sample", this);
            PseudoHapticProfile profile = _profile != null ? _profile : PseudoHapticProfile.CreatePreset(NamedProfiles.PaperExperimentName);
            // The experiment lifted with both hands sharing the weight; an asset is not changed here (a change in play mode stays).
            if (!profile.IsEnabled<TwoHands>())
                Debug.LogWarning("Experiment 2 sample: the profile '" + profile.name + "' has Two Hands off, so each hand lifts the whole bottle; the experiment shared it between both hands: switch Two Hands on in the asset.", this);
            SampleContent.Experiment2(transform, profile);
        }
    }
}
