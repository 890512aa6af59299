using Kosmos.PseudoHaptic.Interaction;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The Interaction SDK transformer on a Grabbable that behaves as the SDK's (issue 24's transformer defects).</summary>
    public sealed class TransformerTests
    {
        static (FakeGrabbable grabbable, PseudoHapticTransformer transformer, PseudoHapticWeight weight) Object(float massKg, PseudoHapticProfile profile = null)
        {
            var table = new GameObject("Table").transform;
            table.position = new Vector3(0, 0.75f, 0.4f);
            var go = new GameObject("Box");
            go.transform.SetParent(table, false);
            go.AddComponent<BoxCollider>().center = new Vector3(0, 0.5f, 0);
            go.AddComponent<Rigidbody>();
            var weight = go.AddComponent<PseudoHapticWeight>();
            weight.Mass = MassSource.Explicit;
            weight.ExplicitMassKg = massKg;
            weight.SpeedSource = StandardSpeedSource.Explicit;
            weight.Profile = profile;
            var grabbable = go.AddComponent<FakeGrabbable>();
            var transformer = go.AddComponent<PseudoHapticTransformer>();
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
    }
}
