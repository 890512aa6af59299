using System.Collections.Generic;
using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.SampleScenes
{
    /// <summary>
    /// Builds the playground when the scene starts: objects from 10 g to 5 kg sharing one profile, and a row of
    /// switches, one per effect, that a fingertip toggles. Put it on an empty GameObject in a scene that has a
    /// hand rig; give it a profile asset to see the switches in the inspector too.
    /// </summary>
    public sealed class PlaygroundSetup : MonoBehaviour
    {
        [Tooltip("The shared profile the switches change; a fresh 'paper' preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile = null;

        void Awake()
        {
            var hands = new List<IHandPoseSource>(SampleContent.HandsInScene("Playground sample", this));
            PseudoHapticProfile profile = _profile != null ? _profile : PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            SampleContent.Playground(transform, profile, hands);
        }
    }
}
