using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.SampleScenes
{
    /// <summary>
    /// Builds the weight discrimination task (two-alternative forced choice) when the scene starts: two balls of
    /// the same look on a table, a "heavier" button in front of each, and a <see cref="DiscriminationTask"/>
    /// for the participant given here, and a <see cref="FingertipPoker"/> per hand of the scene's rig.
    /// Put it on an empty GameObject in a scene that has a hand rig.
    /// </summary>
    public sealed class DiscriminationSetup : MonoBehaviour
    {
        [Tooltip("The balls' profile; the paper preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile = null;
        [Tooltip("The participant's id.")]
        [SerializeField] string _participant = "P1";
        [Tooltip("The study condition of this session (e.g. 'with effect', 'without'); may be empty.")]
        [SerializeField] string _condition = "";
        [Tooltip("The study's seed: each participant and condition runs in its own order drawn from it and their names.")]
        [SerializeField] int _seed = 1;

        void Awake()
        {
            var hands = new System.Collections.Generic.List<IHandPoseSource>(SampleContent.HandsInScene("Discrimination sample", this));
            PseudoHapticProfile profile = _profile != null ? _profile : PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            DiscriminationTask task = DiscriminationStation.Build(transform, profile, _participant, hands); // a fingertip poker per hand answers the buttons
            // Set before the task begins at its Start: the task exists only from here, in play mode.
            task.Condition = _condition;
            task.Seed = _seed;
        }
    }
}
