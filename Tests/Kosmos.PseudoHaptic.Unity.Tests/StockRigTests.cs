using System;
using System.Collections.Generic;
using System.Linq;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Meta;
using Kosmos.PseudoHaptic.Samples;
using Kosmos.PseudoHaptic.SampleScenes;
using Kosmos.PseudoHaptic.Tests.Stock;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;
using UnityEngine.TestTools;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 34 item 2: every sample's setup finds the hands of Meta's stock rig (OVRCameraRig with an OVRHandPrefab under
    /// each hand anchor, nothing of this package on it) and a hand grabs there; with no hand, one warning names what is
    /// missing. Play mode is entered as Unity enters it (the [RuntimeInitializeOnLoadMethod]s run), which registers the
    /// Meta assembly's hand finder.
    /// </summary>
    public sealed class StockRigTests
    {
        static readonly Type[] Setups = { typeof(CalibrationSetup), typeof(Experiment1Setup), typeof(Experiment2Setup), typeof(PlaygroundSetup), typeof(DiscriminationSetup) };

        readonly List<string> _warnings = new List<string>();

        void Collect(string message, string stack, LogType type)
        {
            if (type == LogType.Warning) _warnings.Add(message);
        }

        [SetUp]
        public void EnterPlayMode()
        {
            PlayMode.Enter(typeof(OvrRigHands).Assembly);
            _warnings.Clear();
            Application.logMessageReceived += Collect;
        }

        [TearDown]
        public void StopCollecting() => Application.logMessageReceived -= Collect;

        static double MinimumJerk(double u)
        {
            u = Math.Min(1, Math.Max(0, u));
            return u * u * u * (10 - 15 * u + 6 * u * u);
        }

        [TestCaseSource(nameof(Setups))]
        public void EverySampleFindsTheStockRigsHandsAndAHandGrabsThere(Type setup)
        {
            var (rig, left, right) = StockOvrRig.Build();
            Assert.That(UnityEngine.Object.FindObjectsByType<OvrHandPoseSource>(FindObjectsSortMode.None), Is.Empty, "the stock rig has none of the package's components");
            new GameObject(setup.Name).AddComponent(setup);

            OvrHandPoseSource[] sources = UnityEngine.Object.FindObjectsByType<OvrHandPoseSource>(FindObjectsSortMode.None);
            Assert.That(sources.Select(s => s.gameObject), Is.EquivalentTo(new[] { left.gameObject, right.gameObject }), "a pose source on each OVRHand");
            Assert.That(sources.Select(s => s.OvrHand), Is.EquivalentTo(new[] { left, right }));
            Assert.That(sources.All(s => s.GetComponent<PinchGrab>() != null), Is.True, "and a Pinch Grab");
            Assert.That(sources.Select(s => s.Source), Is.All.EqualTo(OvrHandPoseSource.PositionSource.PinchPoint), "reading the pinch point, where a pinch grabs");
            Assert.That(sources.Select(s => s.Rig), Is.All.SameAs(rig.trackingSpace), "the hold is solved in the rig's tracking space");
            Assert.That(_warnings.Where(w => !w.Contains("tracked from Eye Level")), Is.Empty, "hands were found: no warning about them (the Eye Level one is OnMetasStockRigTheSampleTracksFromTheFloor's)");

            if (setup == typeof(CalibrationSetup))
            {
                StandardSpeedCalibrator calibrator = UnityEngine.Object.FindObjectsByType<StandardSpeedCalibrator>(FindObjectsSortMode.None).Single();
                Assert.That(calibrator.Hand, Is.InstanceOf<OvrHandPoseSource>(), "the calibration reads an OVR hand");
                Assert.That(((OvrHandPoseSource)calibrator.Hand).OvrHand, Is.SameAs(left).Or.SameAs(right));
                return; // nothing to grab at the calibration station: the real golf ball is lifted
            }

            PseudoHapticWeight weight = PseudoHapticWeight.Enabled[0];
            Vector3 at = weight.Collider.bounds.center;
            Vector3 farLeft = new Vector3(-1.5f, 1.2f, -0.6f);
            float startY = weight.transform.position.y;
            Frames.Run(1); // the OVR rig's Start
            for (int i = 0; i < 110; i++)
            {
                double t = i * Frames.DefaultDuration;
                OvrHands.Track(rig, farLeft, at + new Vector3(0, (float)(0.25 * MinimumJerk((t - 0.1) / 0.6)), 0));
                OvrHands.Report(left, tracked: true);
                OvrHands.Report(right, tracked: true, pinching: i >= 3); // the pinch closes at the object
                Frames.Run(1);
            }
            Assert.That(weight.IsHeld, Is.True, weight.name + " is held by the stock rig's right hand");
            Assert.That(weight.transform.position.y - startY, Is.GreaterThan(0.05f), weight.name + " was lifted (m)");
        }

        /// <summary>
        /// A pinch grabs where the fingertips meet: the stock right hand's wrist 11 cm in front of the Playground's 10 g
        /// ball (2 cm radius), its thumb and index tips meeting at the ball's near surface. Read at the wrist (before the
        /// pinch point), the ball was 11 cm away, beyond Reach (6 cm), and a real hand never grabbed it.
        /// </summary>
        [Test]
        public void AStockHandPinchingTheTenGramBallAtItsSurfaceGrabsItWithItsWristBeyondReach()
        {
            var (rig, left, right) = StockOvrRig.Build();
            new GameObject("Playground").AddComponent<PlaygroundSetup>();
            PseudoHapticWeight ball = PseudoHapticWeight.Enabled.Single(w => w.name == "10 g");
            PinchGrab grab = right.GetComponent<PinchGrab>();
            Frames.Run(1); // the OVR rig's Start
            // The runtime's skeleton: the tips 11 cm ahead of the wrist (+z of the hand anchor, which the rig turns as it does the tracking space), meeting.
            OvrHands.InitializeSkeleton(right.GetComponent<OVRSkeleton>(), new Vector3(0, -0.004f, 0.11f), new Vector3(0, 0.004f, 0.11f));

            Vector3 surface = ball.Collider.bounds.center - new Vector3(0, 0, 0.02f); // the side facing the user, who looks along +z
            Vector3 wrist = surface - new Vector3(0, 0, 0.11f);
            Assert.That(Vector3.Distance(ball.Collider.ClosestPoint(wrist), wrist), Is.GreaterThan(grab.Reach), "the wrist is beyond Reach of the ball");
            float startY = ball.transform.position.y;
            Vector3 read = default;
            for (int i = 0; i < 110; i++)
            {
                double t = i * Frames.DefaultDuration;
                OvrHands.Track(rig, new Vector3(-1.5f, 1.2f, -0.6f), wrist + new Vector3(0, (float)(0.25 * MinimumJerk((t - 0.1) / 0.6)), 0));
                OvrHands.Report(left, tracked: true);
                OvrHands.Report(right, tracked: true, pinching: i >= 3);
                Frames.Run(1);
                if (i == 2) read = right.GetComponent<OvrHandPoseSource>().Position;
            }
            Assert.That(ball.IsHeld, Is.True, "the 10 g ball is held");
            Assert.That(ball.transform.position.y - startY, Is.GreaterThan(0.2f), "and lifted with the hand (m)");
            Assert.That(Vector3.Distance(read, surface), Is.LessThan(1e-4f), "the hand was read where the tips meet: " + read);
        }

        /// <summary>
        /// Meta's OVRCameraRig.prefab tracks from Eye Level: y = 0 is the user's eyes at start, and a sample's table (its top
        /// at 0.75 m) floated 0.75 m above them. The samples set the rig to Floor Level, saying so once; a rig already at
        /// Floor Level is left as it is, without a word.
        /// </summary>
        [TestCaseSource(nameof(Setups))]
        public void OnMetasStockRigTheSampleTracksFromTheFloor(Type setup)
        {
            var (rig, _, _) = StockOvrRig.Build();
            OVRManager manager = rig.GetComponent<OVRManager>();
            Assert.That(manager.trackingOriginType, Is.EqualTo(OVRManager.TrackingOrigin.EyeLevel), "as Meta's prefab ships it");
            new GameObject(setup.Name).AddComponent(setup);
            Assert.That(manager.trackingOriginType, Is.EqualTo(OVRManager.TrackingOrigin.FloorLevel));
            Assert.That(_warnings.Count(w => w.Contains("tracked from Eye Level")), Is.EqualTo(1), string.Join("\n", _warnings));

            _warnings.Clear();
            new GameObject(setup.Name + " again").AddComponent(setup);
            Assert.That(_warnings.Count(w => w.Contains("Eye Level")), Is.EqualTo(0), "at Floor Level already: nothing said");
        }

        /// <summary>On the stock rig the one hand component to assign is Meta's OVRHand: it has no pose source until the setup
        /// gives it one, and the calibration fell back to the scene's last pinch hand (the other one, maybe).</summary>
        [Test]
        public void TheCalibrationReadsTheOVRHandAssignedToIt([Values(0, 1)] int which)
        {
            var (_, left, right) = StockOvrRig.Build();
            OVRHand assigned = which == 0 ? left : right;
            var go = new GameObject("Calibration");
            go.SetActive(false); // assigned before Awake, as a scene's serialized field is
            var setup = go.AddComponent<CalibrationSetup>();
            typeof(CalibrationSetup).GetField("_hand", System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Instance)!.SetValue(setup, assigned);
            go.SetActive(true);
            StandardSpeedCalibrator calibrator = UnityEngine.Object.FindObjectsByType<StandardSpeedCalibrator>(FindObjectsSortMode.None).Single();
            Assert.That(((OvrHandPoseSource)calibrator.Hand).OvrHand, Is.SameAs(assigned));
            Assert.That(OVRManager.instance.trackingOriginType, Is.EqualTo(OVRManager.TrackingOrigin.FloorLevel));
        }

        /// <summary>A Calibration given a hand that is already a pose source does not look for the scene's hands, but its table
        /// still stands on the floor: the rig is set to Floor Level all the same.</summary>
        [Test]
        public void TheCalibrationGivenAPoseSourceStillTracksFromTheFloor()
        {
            var (rig, _, right) = StockOvrRig.Build();
            OvrRigHands.AddPoseSources();
            var go = new GameObject("Calibration");
            go.SetActive(false);
            var setup = go.AddComponent<CalibrationSetup>();
            typeof(CalibrationSetup).GetField("_hand", System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Instance)!.SetValue(setup, right.GetComponent<OvrHandPoseSource>());
            go.SetActive(true);
            Assert.That(rig.GetComponent<OVRManager>().trackingOriginType, Is.EqualTo(OVRManager.TrackingOrigin.FloorLevel));
            Assert.That(_warnings.Count(w => w.Contains("tracked from Eye Level")), Is.EqualTo(1));
        }

        [Test]
        public void WithoutAnyHandASampleWarnsOnceNamingTheMissingOVRHand()
        {
            new GameObject("Experiment 1").AddComponent<Experiment1Setup>();
            Assert.That(_warnings, Has.Count.EqualTo(1));
            Assert.That(_warnings[0], Does.StartWith("Experiment 1 sample: no hand to grab with").And.Contain("no enabled OVRHand").And.Contain("OVRHandPrefab under TrackingSpace/LeftHandAnchor"));
        }

        [Test]
        public void WithoutTheMetaSdkTheWarningNamesIt()
        {
            SampleContent.RegisterOvrHands(null); // as when Kosmos.PseudoHaptic.Meta is not compiled
            new GameObject("Calibration").AddComponent<CalibrationSetup>();
            Assert.That(_warnings, Has.Count.EqualTo(1), "the calibration no longer logs an error of its own");
            Assert.That(_warnings[0], Does.StartWith("Calibration sample: no hand").And.Contain("Meta XR Core SDK (com.meta.xr.sdk.core) is not installed"));
        }

        [Test]
        public void TheExperiment1SampleBuildsPaperExperiment1()
        {
            StockOvrRig.Build();
            new GameObject("Experiment 1").AddComponent<Experiment1Setup>();
            Assert.That(PseudoHapticWeight.Enabled.Select(w => w.name), Is.EqualTo(PaperExperiment1.BoxNames.Select(n => "Box " + n)));
            for (int i = 0; i < PseudoHapticWeight.Enabled.Count; i++)
            {
                PseudoHapticWeight w = PseudoHapticWeight.Enabled[i];
                Assert.That(w.Configure(), Is.True, w.ConfigurationError);
                Assert.That(w.GetComponent<BoxCollider>().size, Is.EqualTo(Vector3.one * (float)PaperExperiment1.BoxEdge));
                Assert.That(w.GetComponent<Rigidbody>().mass, Is.EqualTo(PaperExperiment1.Mass(PaperExperiment1.BoxDensities[i])).Within(1e-4), "density × the collider's volume, kg");
                Assert.That(w.Profile.name, Is.EqualTo(PaperExperiment1.ProfileName));
                Assert.That(w.Profile.IsEnabled(new TwoHands().Name), Is.True);
                Assert.That(w.Profile.IsEnabled(new OffsetCorrection().Name), Is.False);
            }
        }

        [Test]
        public void AHandTheRigBuilderAlreadyGaveASourceGetsNoSecond()
        {
            var (rig, left, right) = StockOvrRig.Build();
            var own = left.gameObject.AddComponent<OvrHandPoseSource>();
            own.InjectHand(left);
            Assert.That(OvrRigHands.AddPoseSources(), Is.EqualTo(2));
            Assert.That(left.GetComponents<OvrHandPoseSource>(), Has.Length.EqualTo(1));
            Assert.That(right.GetComponents<OvrHandPoseSource>(), Has.Length.EqualTo(1));
            right.enabled = false;
            Assert.That(OvrRigHands.AddPoseSources(), Is.EqualTo(1), "a disabled OVRHand is not a hand");
        }
    }
}
