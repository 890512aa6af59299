using System;
using Kosmos.PseudoHaptic.Interaction;
using NUnit.Framework;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The per-frame paths a held object takes in a scene, measured for allocation under the double (.NET's per-thread
    /// allocation counter; in Unity the edit-mode suite's AllocatingGCMemory constraint covers the solver itself): Pinch
    /// Grab's frame with the weight it holds (its LateUpdate, the main path without a grab system), and the Interaction
    /// SDK transformer's UpdateTransform on each Move (<see cref="Allocations"/>).
    /// </summary>
    public sealed class HotPathAllocationTests : PlayModeFixture
    {
        static long Allocated(Action frames)
        {
            frames(); // warm
            return Allocations.OfOneInThree(frames);
        }

        [Test]
        public void APinchGrabHoldingAWeightAllocatesNothingPerFrame([Values(HandDrawingMode.HandTrue, HandDrawingMode.HandOnObject)] HandDrawingMode drawing)
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            profile.HandDrawing = drawing;
            PseudoHapticWeight box = Box("2 kg", 2f, default, profile);
            Vector3 start = box.Collider.bounds.center;
            var hand = new ScriptedHand(start) { IsPinching = true };
            var go = Track(new GameObject("hand"));
            go.SetActive(false); // driven by Tick
            var grab = go.AddComponent<PinchGrab>();
            grab.InjectHand(hand);
            grab.HandVisual = Track(new GameObject("Hand Visual")).transform;
            grab.Tick(FrameTime);
            Assert.That(grab.Held, Is.SameAs(box));
            int frame = 0;
            void Frames()
            {
                for (int i = 0; i < 2000; i++, frame++)
                {
                    // Up and down 10 cm and sideways, 30 Hz poses held over 90 Hz frames, now and then untracked.
                    double t = frame / 30 / 30.0;
                    hand.IsTracked = frame % 97 > 3;
                    hand.Track(start + new Vector3(0.05f * (float)Math.Sin(t), 0.05f - 0.05f * (float)Math.Cos(t * 1.3), 0), FrameTime);
                    grab.Tick(FrameTime);
                }
            }
            Assert.That(Allocated(Frames), Is.Zero, "bytes over 2000 frames of a held 2 kg box (xyz, " + drawing + ")");
            Assert.That(grab.Held, Is.SameAs(box), "still held");
        }

        [Test]
        public void TheInteractionSdkTransformerAllocatesNothingPerMove()
        {
            PseudoHapticWeight weight = Box("Box", 2f, default, PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName));
            var grabbable = weight.gameObject.AddComponent<FakeGrabbable>();
            var transformer = weight.gameObject.AddComponent<PseudoHapticTransformer>();
            grabbable.Use(transformer, transformer);
            var left = new FakeHand { Wrist = weight.transform.position + new Vector3(-0.15f, 0.05f, 0) };
            var right = new FakeHand { Wrist = weight.transform.position + new Vector3(0.15f, 0.05f, 0) };
            var a = new FakeHandGrabInteractor(grabbable, 7, left);
            var b = new FakeHandGrabInteractor(grabbable, 8, right);
            a.Grab();
            b.Grab();
            Assert.That(weight.Hold.HandCount, Is.EqualTo(2));
            int frame = 0;
            // Only the Moves are counted: the double's own frame loop (Frames.Run, which advances the clock) is not the package's.
            long Moves()
            {
                long moved = 0;
                for (int i = 0; i < 1000; i++, frame++)
                {
                    Vector3 up = new Vector3(0, 0.0001f * (frame % 100), 0);
                    left.Wrist += up;
                    right.Wrist += up;
                    UnityDouble.Frames.Run(1);
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    a.Move();
                    b.Move();
                    moved += GC.GetAllocatedBytesForCurrentThread() - before;
                }
                return moved;
            }
            Moves(); // warm
            long allocated = Allocations.OfOneInThree(Moves);
            Assert.That(allocated, Is.Zero, "bytes over 2000 Moves, two hands");
            Assert.That(weight.IsHeld, Is.True);
        }
    }
}
