using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Meta;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 26: the weight cue moves with the player. An OVR rig carries a hand that lifts a 2 kg box (under "xyz" with a
    /// 0.25 m break-away) along the same path in the rig's frame while the rig stands still, walks, turns, snaps, teleports
    /// or rides up; the box's path in the rig's frame must be the standing-still one (within 1 mm, its rotation within
    /// 0.1°), and the box stays held. The rig is moved in Update (before the hands are read, as OVR locomotion does) or in
    /// LateUpdate after the grab (a late locomotion: the weight re-places the box through the rig before the frame renders).
    /// </summary>
    public sealed class RigMotionTests : PlayModeFixture
    {
        const double Grab = 0.3, End = 1.8; // s: the rig starts moving after the grab; the run lasts this long

        /// <summary>The hand's tracked pose, in tracking space, per frame (what the OVR runtime reports).</summary>
        [DefaultExecutionOrder(-200)]
        sealed class TrackedHand : MonoBehaviour
        {
            public OVRCameraRig Rig;
            public OVRHand Hand;

            public static Vector3 At(double t)
            {
                double u = Math.Min(1, Math.Max(0, (t - 0.4) / 0.8));
                double s = u * u * u * (10 - 15 * u + 6 * u * u); // minimum jerk
                return new Vector3((float)(0.2 * s), (float)(0.8 + 0.3 * s), 0.4f);
            }

            void Update()
            {
                OvrHands.Track(Rig, new Vector3(-0.3f, 1f, 0.3f), At(Time.timeAsDouble));
                OvrHands.Report(Hand, tracked: true, pinching: true);
            }
        }

        /// <summary>A locomotion system moving the rig's root: in Update before the anchors (order −100), or in LateUpdate after the grab (order 100).</summary>
        [DefaultExecutionOrder(-100)]
        sealed class Locomotion : MonoBehaviour
        {
            public Func<double, Pose> Path;
            public bool Late;

            void Update() { if (!Late) Move(); }
            void LateUpdate() { if (Late) Move(); }

            void Move()
            {
                Pose p = Path(Time.timeAsDouble);
                transform.position = p.position;
                transform.rotation = p.rotation;
            }
        }

        static Pose Yaw(Vector3 position, float yaw) => new Pose(position, Quaternion.Euler(0, yaw, 0));

        static readonly Dictionary<string, Func<double, Pose>> Motions = new Dictionary<string, Func<double, Pose>>
        {
            ["still"] = t => Yaw(Vector3.zero, 0),
            ["walk 1.5 m/s"] = t => Yaw(new Vector3((float)(1.5 * Math.Max(0, t - Grab)), 0, 0), 0),
            ["turn 90°/s"] = t => Yaw(Vector3.zero, (float)(90 * Math.Max(0, t - Grab))),
            ["snap turns of 45°"] = t => Yaw(Vector3.zero, t < Grab ? 0 : 45 * (float)Math.Floor((t - Grab) / 0.4 + 1)),
            ["teleport 6.7 m, heading 90°"] = t => t < 0.6 ? Yaw(Vector3.zero, 0) : Yaw(new Vector3(6, 0, -3), 90),
            ["elevator 1 m/s up"] = t => Yaw(new Vector3(0, (float)(1.0 * Math.Max(0, t - Grab)), 0), 0),
            ["walk, turn and ride at once"] = t => Yaw(new Vector3((float)(1.0 * Math.Max(0, t - Grab)), (float)(-2 * Math.Max(0, t - Grab)), 0), (float)(-60 * Math.Max(0, t - Grab))),
        };

        /// <summary>The box's position and rotation in the rig's frame, frame by frame, and whether it was held to the end.</summary>
        (List<Vector3> path, List<Quaternion> turn, bool held) Run(Func<double, Pose> motion, bool late)
        {
            var rigGo = new GameObject("OVRCameraRig");
            OVRCameraRig rig = rigGo.AddComponent<OVRCameraRig>();
            var locomotion = rigGo.AddComponent<Locomotion>();
            locomotion.Path = motion;
            locomotion.Late = late;
            var handGo = new GameObject("OVRHandPrefab");
            handGo.transform.SetParent(rig.rightHandAnchor, false);
            OVRHand hand = handGo.AddComponent<OVRHand>();
            var source = handGo.AddComponent<OvrHandPoseSource>();
            source.Tracked = rig.rightHandAnchor;
            handGo.AddComponent<PinchGrab>().InjectHand(source);
            var driver = handGo.AddComponent<TrackedHand>();
            driver.Rig = rig;
            driver.Hand = hand;

            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            profile.SetEnabled<BreakAway>(true);
            PseudoHapticWeight weight = Box("2 kg", 2f, default, profile);

            var path = new List<Vector3>();
            var turn = new List<Quaternion>();
            while (Time.timeAsDouble < End)
            {
                Frames.Run(1);
                path.Add(rig.trackingSpace.InverseTransformPoint(weight.transform.position));
                turn.Add(Quaternion.Inverse(rig.trackingSpace.rotation) * weight.transform.rotation);
            }
            bool held = weight.IsHeld;
            UnityEngine.Object.DestroyImmediate(rigGo);
            UnityEngine.Object.DestroyImmediate(weight.gameObject);
            UnityEngine.Object.DestroyImmediate(profile);
            UnityDouble.Frames.ResetClock(); // the next run starts at t = 0 too
            return (path, turn, held);
        }

        static IEnumerable<TestCaseData> Cases()
        {
            foreach (string name in Motions.Keys)
            {
                if (name == "still") continue;
                yield return new TestCaseData(name, false).SetName("In the rig's frame the box's path is the standing-still one: " + name + ", rig moved in Update");
                yield return new TestCaseData(name, true).SetName("In the rig's frame the box's path is the standing-still one: " + name + ", rig moved in LateUpdate after the grab");
            }
        }

        [TestCaseSource(nameof(Cases))]
        public void TheRigsMotionCarriesTheHeldBoxRigidly(string motion, bool late)
        {
            var still = Run(Motions["still"], false);
            Assert.That(still.held, Is.True, "standing still, the lift keeps the box");
            double lift = still.path[still.path.Count - 1].y - still.path[0].y;
            Assert.That(lift, Is.GreaterThan(0.05), "the box was lifted in the standing-still run (" + lift + " m of the hand's 0.3 m: 2 kg lags)");
            var moving = Run(Motions[motion], late);
            Assert.That(moving.held, Is.True, "the rig's motion never breaks the box away");
            Assert.That(moving.path.Count, Is.EqualTo(still.path.Count));
            double worst = 0, worstTurn = 0;
            for (int i = 0; i < still.path.Count; i++)
            {
                worst = Math.Max(worst, Vector3.Distance(still.path[i], moving.path[i]));
                worstTurn = Math.Max(worstTurn, Quaternion.Angle(still.turn[i], moving.turn[i]));
            }
            Assert.That(worst, Is.LessThanOrEqualTo(0.001), "m, the largest gap between the two paths in the rig's frame");
            Assert.That(worstTurn, Is.LessThanOrEqualTo(0.1), "degrees, the box's rotation in the rig's frame");
        }
    }
}
