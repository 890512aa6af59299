using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Creates test objects under one upright, unit-scale surface and destroys them after each test.</summary>
    public abstract class PlayModeFixture
    {
        protected const float FrameTime = 1f / 90f; // Quest 2 at 90 Hz; hand poses at 30 Hz

        readonly List<GameObject> _created = new List<GameObject>();
        protected Transform Surface;

        [SetUp]
        public void CreateSurface()
        {
            Surface = Track(new GameObject("Surface")).transform;
            Surface.position = new Vector3(0, 0.75f, 0.4f);
            // Something to rest on when physics runs ([UnityTest]s) and after a release.
            var top = new GameObject("Table top");
            top.transform.SetParent(Surface, false);
            var slab = top.AddComponent<BoxCollider>();
            slab.size = new Vector3(10f, 0.1f, 10f);
            slab.center = new Vector3(0, -0.05f, 0);
        }

        [TearDown]
        public void DestroyAll()
        {
            foreach (GameObject go in _created)
                if (go != null) Object.DestroyImmediate(go);
            _created.Clear();
        }

        protected GameObject Track(GameObject go)
        {
            _created.Add(go);
            return go;
        }

        /// <summary>A box resting on the surface (pivot at its bottom) with a Rigidbody and the weight.</summary>
        protected PseudoHapticWeight Box(string name, float massKg, Vector3 localPosition = default, PseudoHapticProfile profile = null)
        {
            var go = new GameObject(name);
            go.transform.SetParent(Surface, false);
            go.transform.localPosition = localPosition;
            var box = go.AddComponent<BoxCollider>();
            box.size = Vector3.one * 0.1f;
            box.center = new Vector3(0, 0.05f, 0);
            go.AddComponent<Rigidbody>();
            var weight = go.AddComponent<PseudoHapticWeight>();
            weight.Mass = MassSource.Explicit;
            weight.ExplicitMassKg = massKg;
            weight.SpeedSource = StandardSpeedSource.Explicit;
            weight.Profile = profile;
            return weight;
        }

        /// <summary>
        /// Holds <paramref name="weight"/> and lifts the hand by <paramref name="rise"/> m over <paramref name="duration"/> s
        /// (minimum jerk, 30 Hz poses, 90 Hz frames), then holds still for <paramref name="hold"/> s. Returns the final local y.
        /// </summary>
        protected static float Lift(PseudoHapticWeight weight, float rise, float duration, float hold = 0.3f)
        {
            var hand = new ScriptedHand(weight.transform.position);
            Vector3 start = hand.Position;
            Assert.That(weight.BeginHold(hand), Is.True, weight.ConfigurationError);
            int frames = Mathf.CeilToInt((duration + hold) / FrameTime);
            for (int i = 1; i <= frames; i++)
            {
                double u = i * FrameTime / duration;
                hand.Track(start + new Vector3(0, (float)(rise * ScriptedHand.MinimumJerk(u)), 0), FrameTime);
                weight.Step(hand, FrameTime);
            }
            return weight.transform.localPosition.y;
        }
    }
}
