using Oculus.Interaction;
using Kosmos.PseudoHaptic.Interaction;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The Interaction SDK transformer on a Grabbable that behaves as the SDK's (issue 24's transformer defects).</summary>
    public sealed class TransformerTests : PlayModeFixture
    {
        (FakeGrabbable grabbable, PseudoHapticTransformer transformer, PseudoHapticWeight weight) Object(float massKg, PseudoHapticProfile profile = null)
        {
            PseudoHapticWeight weight = Box("Box", massKg, default, profile);
            var grabbable = weight.gameObject.AddComponent<FakeGrabbable>();
            var transformer = weight.gameObject.AddComponent<PseudoHapticTransformer>();
            grabbable.Use(transformer, transformer);
            return (grabbable, transformer, weight);
        }

        [Test]
        public void AHandGrabWithoutItsHandHoldsTheObjectStillInsteadOfThrowing()
        {
            var (grabbable, _, weight) = Object(1f);
            var hand = new FakeHand { Wrist = weight.transform.position + new Vector3(0, 0.05f, 0) };
            var interactor = new FakeHandGrabInteractor(grabbable, 7, hand);
            interactor.Grab();
            Assert.That(weight.IsHeld, Is.True);
            interactor.Hand = null; // its hand destroyed, or never wired
            Vector3 before = weight.transform.position;
            for (int i = 0; i < 30; i++)
            {
                Frames.Run(1);
                interactor.Move(); // the SDK's Move makes the Grabbable update its transformer
            }
            Assert.That(weight.IsHeld, Is.True);
            Assert.That(weight.transform.position, Is.EqualTo(before), "a lost hand holds the object still");
        }

        /// <summary>
        /// A grab that is not a hand's (a ray or a controller) is read at the Grabbable's grab point of that grab. With the
        /// Grabbable's AddNewPointsToFront (PointableElement), a later Select's point goes first: the transformer read the
        /// index of its own join order, so the first grab (the ray) followed the hand's point. The same grabs must move
        /// the object alike either way.
        /// </summary>
        [Test]
        public void AGrabThatIsNotAHandsFollowsItsOwnPointWhereTheGrabbableAddsNewPointsToTheFront()
        {
            Vector3[] Lift(bool toFront)
            {
                var (grabbable, _, weight) = Object(1f);
                grabbable.AddNewPointsToFront = toFront;
                Vector3 start = weight.transform.position, ray = start + new Vector3(0.15f, 0.05f, 0);
                grabbable.ProcessPointerEvent(new PointerEvent(9, PointerEventType.Hover, new Pose(ray, Quaternion.identity)));
                grabbable.ProcessPointerEvent(new PointerEvent(9, PointerEventType.Select, new Pose(ray, Quaternion.identity)));
                var hand = new FakeHand { Wrist = start + new Vector3(-0.15f, 0.05f, 0) };
                var interactor = new FakeHandGrabInteractor(grabbable, 7, hand);
                interactor.Grab(); // the hand joins second, and stays where it is
                var path = new Vector3[60];
                for (int f = 0; f < path.Length; f++)
                {
                    ray.y += 0.005f; // the ray's point lifts 0.3 m in 60 frames
                    Frames.Run(1);
                    grabbable.ProcessPointerEvent(new PointerEvent(9, PointerEventType.Move, new Pose(ray, Quaternion.identity)));
                    interactor.Move();
                    path[f] = weight.transform.position - start;
                }
                Assert.That(weight.IsHeld, Is.True);
                return path;
            }
            Vector3[] atTheEnd = Lift(false), atTheFront = Lift(true);
            Assert.That(atTheEnd[atTheEnd.Length - 1].y, Is.GreaterThan(0.05f), "the ray's lift moves the object");
            Assert.That(atTheFront, Is.EqualTo(atTheEnd));
        }

        /// <summary>
        /// The weight switched off and on mid-grab (a study script toggling the effect): its hold ended, the Grabbable kept
        /// the grab, and the transformer went on stepping a weight that held nothing, so the object hung where it was until
        /// the hand let go. It now holds it again from where the hand is (as the XRI transformer does).
        /// </summary>
        [Test]
        public void TheWeightSwitchedOffAndOnMidGrabIsHeldAgain()
        {
            var (grabbable, _, weight) = Object(1f);
            var hand = new FakeHand { Wrist = weight.transform.position + new Vector3(0, 0.05f, 0) };
            var interactor = new FakeHandGrabInteractor(grabbable, 7, hand);
            interactor.Grab();
            void Frame(float rise)
            {
                hand.Wrist += new Vector3(0, rise, 0);
                Frames.Run(1);
                interactor.Move();
            }
            for (int i = 0; i < 10; i++) Frame(0.002f);
            weight.enabled = false;
            Assert.That(weight.IsHeld, Is.False);
            for (int i = 0; i < 10; i++) Frame(0.002f);
            weight.enabled = true;
            Vector3 before = weight.transform.position;
            for (int i = 0; i < 90; i++) Frame(i < 30 ? 0.004f : 0f); // 0.12 m up, then still for a second
            Assert.That(weight.IsHeld, Is.True);
            Assert.That(weight.transform.position.y - before.y, Is.GreaterThan(0.03f), "the object follows the hand again (1 kg: about 0.4 of the hand's 0.12 m)");
        }

        [Test]
        public void ABreakAwayCancelsBothGrabsOnceAndBeginsNothingAgain()
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            profile.SetEnabled<BreakAway>(true);
            profile.SetEnabled<OffsetCorrection>(false); // which would keep the lag under the break-away distance
            var (grabbable, _, weight) = Object(5f, profile);
            int began = 0, ended = 0;
            void Began(PseudoHapticWeight w) => began++;
            void Ended(PseudoHapticWeight w) => ended++;
            PseudoHapticWeight.HoldBegan += Began;
            PseudoHapticWeight.HoldEnded += Ended;
            Vector3 centre = weight.transform.position + new Vector3(0, 0.05f, 0);
            var left = new FakeHand { Wrist = centre + new Vector3(-0.04f, 0, 0) };
            var right = new FakeHand { Wrist = centre + new Vector3(0.04f, 0, 0) };
            var l = new FakeHandGrabInteractor(grabbable, 1, left);
            var r = new FakeHandGrabInteractor(grabbable, 2, right);
            l.Grab();
            r.Grab();
            Assert.That(weight.Hold.HandCount, Is.EqualTo(2));
            for (int i = 1; i <= 60 && grabbable.Selecting > 0; i++)
            {
                Frames.Run(1);
                Vector3 up = new Vector3(0, 0.8f * Mathf.Clamp01(i / 36f), 0);
                left.Wrist = centre + new Vector3(-0.04f, 0, 0) + up;
                right.Wrist = centre + new Vector3(0.04f, 0, 0) + up;
                l.Move();
                r.Move();
            }
            PseudoHapticWeight.HoldBegan -= Began;
            PseudoHapticWeight.HoldEnded -= Ended;
            Assert.That(grabbable.Selecting, Is.EqualTo(0), "every grab point cancelled");
            Assert.That(weight.IsHeld, Is.False);
            Assert.That(began, Is.EqualTo(1), "the hold began once");
            Assert.That(ended, Is.EqualTo(1), "and ended once");
        }

        /// <summary>The hand moves in real time: the same lift through the Interaction SDK moves the box the same way at any Time.timeScale.</summary>
        [Test]
        public void TheGamesTimeScaleDoesNotChangeALift()
        {
            float[] Lift(float scale)
            {
                Time.timeScale = scale;
                try
                {
                    var (grabbable, _, weight) = Object(2f);
                    Vector3 start = weight.transform.position + new Vector3(0, 0.05f, 0);
                    var hand = new FakeHand { Wrist = start };
                    var interactor = new FakeHandGrabInteractor(grabbable, 3, hand);
                    interactor.Grab();
                    var path = new float[110];
                    for (int i = 0; i < path.Length; i++)
                    {
                        Frames.Run(1);
                        float u = Mathf.Clamp01(i / 80f);
                        hand.Wrist = start + new Vector3(0, 0.25f * u * u * (3 - 2 * u), 0);
                        interactor.Move();
                        path[i] = weight.transform.position.y;
                    }
                    UnityEngine.Object.DestroyImmediate(weight.gameObject);
                    UnityDouble.Frames.ResetClock();
                    return path;
                }
                finally
                {
                    Time.timeScale = 1;
                }
            }
            float[] normal = Lift(1f);
            Assert.That(normal[normal.Length - 1] - normal[0], Is.GreaterThan(0.05f), "the box rose");
            Assert.That(Lift(0.5f), Is.EqualTo(normal).Within(1e-5f), "slow motion");
            Assert.That(Lift(0f), Is.EqualTo(normal).Within(1e-5f), "paused");
        }

        /// <summary>Issue 26 with the Interaction SDK: the rig (its tracking space) teleports and turns mid-lift; in its frame the path is the standing-still one.</summary>
        [Test]
        public void ATeleportMidLiftCarriesTheObjectRigidlyThroughTheTransformersRig()
        {
            System.Collections.Generic.List<Vector3> Lift(bool teleport)
            {
                var rig = new GameObject("TrackingSpace").transform;
                var (grabbable, transformer, weight) = Object(2f);
                transformer.Rig = rig;
                var hand = new FakeHand();
                Vector3 start = weight.transform.position + new Vector3(0, 0.05f, 0); // the rig is at the origin at the grab
                hand.Wrist = start;
                var interactor = new FakeHandGrabInteractor(grabbable, 4, hand);
                interactor.Grab();
                var path = new System.Collections.Generic.List<Vector3>();
                for (int i = 1; i <= 90; i++)
                {
                    Frames.Run(1);
                    if (teleport && i == 30)
                    {
                        rig.position = new Vector3(4, 0.5f, -2);
                        rig.rotation = Quaternion.Euler(0, 135, 0);
                    }
                    // The tracked hand: a lift in the rig's frame, reported in the world through the rig (as the SDK's hands are).
                    float u = Mathf.Clamp01(i / 60f);
                    hand.Wrist = rig.TransformPoint(start + new Vector3(0, 0.25f * u * u * (3 - 2 * u), 0));
                    interactor.Move();
                    path.Add(rig.InverseTransformPoint(weight.transform.position));
                }
                Assert.That(weight.IsHeld, Is.True);
                UnityEngine.Object.DestroyImmediate(weight.gameObject);
                UnityEngine.Object.DestroyImmediate(rig.gameObject);
                UnityDouble.Frames.ResetClock();
                return path;
            }
            var still = Lift(false);
            var moved = Lift(true);
            Assert.That(still[still.Count - 1].y - still[0].y, Is.GreaterThan(0.05f), "the box rose");
            for (int i = 0; i < still.Count; i++)
                Assert.That(Vector3.Distance(still[i], moved[i]), Is.LessThanOrEqualTo(0.001f), "frame " + i);
        }
    }
}
