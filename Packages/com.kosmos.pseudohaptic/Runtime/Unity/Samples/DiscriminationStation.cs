using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Samples
{
    /// <summary>
    /// The "Discrimination" sample's content: a table with two balls of the same look (explicit masses, set by
    /// the task for every trial), an answer button in front of each, a text display, the
    /// <see cref="DiscriminationTask"/> wired to them, and a <see cref="FingertipPoker"/> per hand, without which no
    /// button can be poked (a simulated hand pokes with its own position, a hand with a skeleton with its index tip).
    /// </summary>
    public static class DiscriminationStation
    {
        const float BallRadius = 0.035f;

        public static DiscriminationTask Build(Transform root, PseudoHapticProfile profile, string participant, IReadOnlyList<IHandPoseSource> hands = null)
            => Build(root, profile, participant, hands, new Vector3(0, SampleContent.TableHeight, 0.45f), userCueStrength: true);

        /// <summary>The same with the table at <paramref name="tableAt"/>; <paramref name="userCueStrength"/> false renders both
        /// balls at the default cue strength whatever the user's (the calibration's cue-strength staircase, issue 31).</summary>
        public static DiscriminationTask Build(Transform root, PseudoHapticProfile profile, string participant, IReadOnlyList<IHandPoseSource> hands, Vector3 tableAt, bool userCueStrength)
        {
            if (hands != null)
                foreach (IHandPoseSource hand in hands) Poker(root, hand);
            Transform surface = SampleContent.Table(root, "Table", tableAt, new Vector2(0.9f, 0.5f));
            // Same look, no names: the labels say only the side.
            var left = SampleContent.Ball(surface, "Left", new Vector3(-0.2f, 0, 0.05f), BallRadius, 0.5f, profile);
            var right = SampleContent.Ball(surface, "Right", new Vector3(0.2f, 0, 0.05f), BallRadius, 0.5f, profile);
            left.UserCueStrength = right.UserCueStrength = userCueStrength;
            var leftButton = Button(surface, "Left Heavier", new Vector3(-0.2f, 0.02f, -0.17f));
            var rightButton = Button(surface, "Right Heavier", new Vector3(0.2f, 0.02f, -0.17f));
            TextMesh display = SampleContent.Label(surface, "Lift both objects, then poke the heavier side.", new Vector3(0, 0.45f, 0.2f));
            display.characterSize = 0.01f;

            var go = new GameObject("Discrimination Task");
            go.transform.SetParent(root, false);
            go.SetActive(false); // its Awake wires the buttons: it must see them, so it wakes after they are set
            var task = go.AddComponent<DiscriminationTask>();
            task.Inject(left, right, leftButton, rightButton, display);
            task.Participant = participant;
            go.SetActive(true);
            return task;
        }

        /// <summary>A fingertip poker for <paramref name="hand"/>: following a simulated hand itself, else looking for its index tip
        /// under it. A hand that already has one (another station of the scene made it) keeps it: one poker per hand.</summary>
        public static FingertipPoker Poker(Transform root, IHandPoseSource hand)
        {
            if (!(hand is Component c)) return null;
            foreach (FingertipPoker existing in Object.FindObjectsByType<FingertipPoker>(FindObjectsSortMode.None))
                if (ReferenceEquals(existing.Hand, hand)) return existing;
            var go = new GameObject("Fingertip Poker (" + c.name + ")");
            go.transform.SetParent(root, false);
            var poker = go.AddComponent<FingertipPoker>();
            poker.InjectHand(hand);
            if (hand is TransformHandPoseSource simulated) poker.Follow = simulated.Tracked;
            else poker.FindUnder = c.transform;
            return poker;
        }

        static DiscriminationButton Button(Transform surface, string name, Vector3 localPosition)
        {
            var go = new GameObject(name);
            go.transform.SetParent(surface, false);
            go.transform.localPosition = localPosition;
            var collider = go.AddComponent<BoxCollider>();
            collider.isTrigger = true;
            collider.size = new Vector3(0.12f, 0.05f, 0.08f);
            var face = GameObject.CreatePrimitive(PrimitiveType.Cube);
            face.name = "Face";
            Object.DestroyImmediate(face.GetComponent<Collider>());
            face.transform.SetParent(go.transform, false);
            face.transform.localScale = new Vector3(0.12f, 0.02f, 0.08f);
            SampleContent.Label(go.transform, "heavier", new Vector3(0, 0.04f, 0));
            return go.AddComponent<DiscriminationButton>();
        }
    }
}
