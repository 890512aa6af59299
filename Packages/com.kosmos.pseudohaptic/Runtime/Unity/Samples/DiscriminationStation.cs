using UnityEngine;

namespace Kosmos.PseudoHaptic.Samples
{
    /// <summary>
    /// The "Discrimination" sample's content: a table with two balls of the same look (explicit masses, set by
    /// the task for every trial), an answer button in front of each, a text display, and the
    /// <see cref="DiscriminationTask"/> wired to them.
    /// </summary>
    public static class DiscriminationStation
    {
        const float BallRadius = 0.035f;

        public static DiscriminationTask Build(Transform root, PseudoHapticProfile profile, string participant)
        {
            Transform surface = SampleContent.Table(root, "Table", new Vector3(0, SampleContent.TableHeight, 0.45f), new Vector2(0.9f, 0.5f));
            // Same look, no names: the labels say only the side.
            var left = SampleContent.Ball(surface, "Left", new Vector3(-0.2f, 0, 0.05f), BallRadius, 0.5f, profile);
            var right = SampleContent.Ball(surface, "Right", new Vector3(0.2f, 0, 0.05f), BallRadius, 0.5f, profile);
            var leftButton = Button(surface, "Left Heavier", new Vector3(-0.2f, 0.02f, -0.17f));
            var rightButton = Button(surface, "Right Heavier", new Vector3(0.2f, 0.02f, -0.17f));
            TextMesh display = SampleContent.Label(surface, "Lift both objects, then poke the heavier side.", new Vector3(0, 0.45f, 0.2f));
            display.characterSize = 0.01f;

            var go = new GameObject("Discrimination Task");
            go.transform.SetParent(root, false);
            var task = go.AddComponent<DiscriminationTask>();
            task.Inject(left, right, leftButton, rightButton, display);
            task.Participant = participant;
            return task;
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
