using Kosmos.PseudoHaptic.Samples;
using UnityEngine;

namespace Kosmos.PseudoHaptic.SampleScenes
{
    /// <summary>
    /// Builds the calibration station (Son et al. 2022, Fig. 6a) when the scene starts: a table, a marker for
    /// the golf ball, instructions, and a StandardSpeedCalibrator reading the hand that holds the ball.
    /// Put it on an empty GameObject in a scene that has a hand rig.
    /// </summary>
    public sealed class CalibrationSetup : MonoBehaviour
    {
        [Tooltip("The hand that holds the golf ball (an IHandPoseSource, or Meta's OVRHand); the scene's last pinch hand when empty.")]
        [SerializeField] MonoBehaviour _hand = null;

        void Awake()
        {
            IHandPoseSource hand = HandSourceField.Resolve<IHandPoseSource>(_hand);
            if (hand != null) SampleContent.TrackFromTheFloor("Calibration sample", this); // the hands' search below does it too
            else
            {
                var hands = SampleContent.HandsInScene("Calibration sample", this); // warns, naming what is missing, when it finds none
                // An assigned OVRHand (the one hand component Meta's stock rig has) got its pose source just now.
                hand = HandSourceField.Resolve<IHandPoseSource>(_hand);
                if (hand == null)
                {
                    if (hands.Count == 0) return;
                    hand = hands[hands.Count - 1];
                }
            }
            SampleContent.CalibrationStation(transform, hand);
        }
    }
}
