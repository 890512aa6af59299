using System;
using System.Reflection;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Samples;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Issue 24: a component's bad setting fails loudly when it is set, never every frame.</summary>
    public sealed class SettingsValidationTests : PlayModeFixture
    {
        static void SetField(object target, string field, object value) =>
            target.GetType().GetField(field, BindingFlags.Instance | BindingFlags.NonPublic).SetValue(target, value);

        T Inactive<T>(string name) where T : Component
        {
            var go = Track(new GameObject(name));
            go.SetActive(false);
            return go.AddComponent<T>();
        }

        [TestCase(-0.01f)]
        [TestCase(float.NaN)]
        [TestCase(float.PositiveInfinity)]
        public void AReachSetInCodeMustBeAFiniteLengthAndTheErrorNamesIt(float reach)
        {
            var grab = Inactive<PinchGrab>("hand");
            Assert.That(() => grab.Reach = reach, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("Reach"));
            Assert.That(grab.Reach, Is.EqualTo(0.06f), "the old reach stays");
        }

        [Test]
        public void ASerializedNaNReachIsReportedWhenTheGrabWakesAndTheGrabStaysOff()
        {
            var grab = Inactive<PinchGrab>("hand");
            SetField(grab, "_reach", float.NaN);
            LogAssert.Expect(LogType.Error, new Regex("Reach must be finite"));
            grab.gameObject.SetActive(true);
            Assert.That(grab.enabled, Is.False);
        }

        [Test]
        public void AFingertipRadiusMustBePositive()
        {
            var poker = Inactive<FingertipPoker>("tip");
            Assert.That(() => poker.Radius = 0f, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("Radius"));
            SetField(poker, "_radius", -1f);
            LogAssert.Expect(LogType.Error, new Regex("Radius must be finite and greater than 0"));
            poker.gameObject.SetActive(true);
            Assert.That(poker.Collider.radius, Is.GreaterThan(0f), "the collider keeps a real radius");
        }

        [Test]
        public void APanelsSizeAndTextSizeMustBePositive()
        {
            var panel = Inactive<QuestionnairePanel>("panel");
            Assert.That(() => panel.TextSize = 0f, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("TextSize"));
            Assert.That(() => panel.Size = new Vector2(0.6f, float.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("Size.y"));
            SetField(panel, "_textSize", -0.004f);
            LogAssert.Expect(LogType.Error, new Regex("Text Size must be finite"));
            panel.gameObject.SetActive(true);
            panel.Show(); // builds with the defaults, finite everywhere
            Assert.That(float.IsNaN(panel.BackButton.transform.localPosition.x), Is.False);
        }

        [Test]
        public void AnEffectSwitchForAnUnknownEffectSaysSoOnceAndStaysOff()
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            LogAssert.Expect(LogType.Error, new Regex("effect 'weight-gian' is unknown"));
            EffectSwitch s = EffectSwitch.Create(Surface, "weight-gian", Vector3.zero, profile, new IHandPoseSource[0]);
            Track(s.gameObject);
            Assert.That(s.enabled, Is.False);
            s.Toggle(); // nothing to toggle, nothing thrown
            Assert.That(profile.IsEnabled<WeightGain>(), Is.True);
            UnityEngine.Object.DestroyImmediate(profile);
        }

        [Test]
        public void ADiscriminationObjectWhoseMassComesFromItsRigidbodyIsRefused()
        {
            PseudoHapticWeight left = Box("left", 0.5f, new Vector3(-0.2f, 0, 0)), right = Box("right", 0.5f, new Vector3(0.2f, 0, 0));
            left.Mass = MassSource.Rigidbody; // the task's masses would never reach the solver
            var task = Inactive<DiscriminationTask>("task");
            task.Inject(left, right, null, null, null);
            LogAssert.Expect(LogType.Error, new Regex("left object's Mass Source is Rigidbody"));
            Assert.That(task.Begin(), Is.False);
            Assert.That(task.Error, Does.Contain("Explicit"));
            Assert.That(task.Session, Is.Null);
        }
    }
}
