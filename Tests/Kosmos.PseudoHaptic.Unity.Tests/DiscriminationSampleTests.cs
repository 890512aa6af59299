using System.IO;
using Kosmos.PseudoHaptic.Samples;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 24: the Discrimination sample could not be answered (no hand had a fingertip poker, and its buttons are
    /// triggers only). Here a simulated hand lifts both balls and pokes a button, over the double's frames and triggers.
    /// Under the double only: the task writes its trials file under persistentDataPath, a temporary folder here.
    /// </summary>
    public sealed class DiscriminationSampleTests
    {
        static TransformHandPoseSource Hand(string name, Vector3 at)
        {
            var go = new GameObject(name);
            go.transform.position = at;
            return go.AddComponent<TransformHandPoseSource>();
        }

        [Test]
        public void AHandPokingTheRightButtonAfterBothLiftsAnswersTheTrial()
        {
            var root = new GameObject("Sample").transform;
            TransformHandPoseSource left = Hand("Left Hand", new Vector3(-0.3f, 1.2f, 0.2f)), right = Hand("Right Hand", new Vector3(0.3f, 1.2f, 0.2f));
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            DiscriminationTask task = DiscriminationStation.Build(root, profile, "P1", new IHandPoseSource[] { left, right });
            Frames.Run(2); // Start begins the session
            Assert.That(task.Session, Is.Not.Null, task.Error);
            foreach (PseudoHapticWeight ball in PseudoHapticWeight.Enabled)
            {
                Assert.That(ball.BeginHold(ball.transform.position), Is.True, ball.ConfigurationError);
                ball.EndHold();
            }
            Assert.That(task.Session.CanAnswer, Is.True, "both were lifted");

            Transform button = GameObject.Find("Right Heavier").transform;
            right.transform.position = button.position; // the fingertip into the button
            Frames.For(0.2);
            Assert.That(task.WaitForSaves(), Is.True, task.Error); // written in the background; a later frame's Update delivers it
            Assert.That(task.Session.AnsweredCount, Is.EqualTo(1), task.Error);
            Assert.That(File.ReadAllLines(task.TrialsPath), Has.Length.EqualTo(2), "the header and the answer");
        }

        [Test]
        public void AFingertipRestingInAButtonSearchesNoComponentPerFrame()
        {
            var root = new GameObject("Sample").transform;
            TransformHandPoseSource hand = Hand("Hand", new Vector3(0, 1.5f, 0));
            var go = new GameObject("Button");
            go.AddComponent<BoxCollider>().isTrigger = true;
            var button = go.AddComponent<DiscriminationButton>();
            DiscriminationStation.Poker(root, hand);
            hand.transform.position = go.transform.position;
            Frames.For(0.1); // the contact begins
            long searches = Diagnostics.ComponentSearches;
            Frames.For(1.0); // and lasts fifty fixed steps
            Assert.That(Diagnostics.ComponentSearches - searches, Is.Zero, "component searches while the fingertip rests in the button");
            Assert.That(button, Is.Not.Null);
        }
    }
}
