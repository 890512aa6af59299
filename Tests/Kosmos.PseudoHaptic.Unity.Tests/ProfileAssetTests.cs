using System.Globalization;
using System.Linq;
using Kosmos.PseudoHaptic.Editor;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;
using UnityEditor;
using UnityEngine.TestTools;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 33 under the double: the profile asset as a list of effects. Its inspector adds (the "Add Effect" menu lists every
    /// registered effect with its summary), removes, moves within a stage and edits a setting; an old asset's flat fields are
    /// read once (JsonUtility.FromJsonOverwrite, which calls OnAfterDeserialize as Unity's YAML load does) and converted; an
    /// effect from this assembly (not the package's) is listed, built, exported and read back.
    /// </summary>
    public sealed class ProfileAssetTests
    {
        static PseudoHapticProfileEditor Inspector(PseudoHapticProfile profile)
        {
            var inspector = ScriptableObject.CreateInstance<PseudoHapticProfileEditor>();
            inspector.target = profile;
            return inspector;
        }

        [Test]
        public void AddEffectListsEveryEffectWithItsSummaryAndAddsTheChosenOne()
        {
            EffectRegistry.Register(Wobble.Descriptor);
            var profile = PseudoHapticProfile.CreatePreset(NamedProfiles.GainName);
            var inspector = Inspector(profile);
            GUILayoutDriver.Click("Add Effect");
            inspector.OnInspectorGUI();
            var menu = UnityDouble.Editor.MenuShown;
            Assert.That(menu.Select(m => m.Text), Is.EqualTo(EffectRegistry.All.Select(ProfileEffectList.MenuText)));
            Assert.That(menu.Select(m => m.Tooltip), Is.EqualTo(EffectRegistry.All.Select(d => d.Summary)));
            Assert.That(menu.Where(m => !m.Enabled).Select(m => m.Text.Split('/')[1].Split(' ')[0]), Is.EquivalentTo(new[] { "motion-deadband", "weight-gain", "floor-clamp" }));
            Assert.That(menu.Any(m => m.Text == "Position/wobble — raises the object by a fixed height" && m.Enabled), "an effect of another assembly is offered");

            UnityDouble.Editor.ChooseMenuItem(ProfileEffectList.MenuText(OffsetCorrection.Descriptor));
            Assert.That(profile.IsEnabled("offset-correction"), Is.True);
            Assert.That(profile.Build().Find<OffsetCorrection>().Threshold, Is.EqualTo(0.2));
            Assert.That(profile.Effects.Select(e => e.effect), Is.EqualTo(new[] { "motion-deadband", "weight-gain", "offset-correction", "floor-clamp" }), "in stage order");
        }

        [Test]
        public void TheInspectorRemovesAnEffectMovesItWithinItsStageAndEditsASetting()
        {
            var profile = PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            var inspector = Inspector(profile);
            int version = profile.Version;
            GUILayoutDriver.Click("Remove speed-cap");
            inspector.OnInspectorGUI();
            Assert.That(profile.IsEnabled<SpeedCap>(), Is.False);
            Assert.That(profile.Version, Is.Not.EqualTo(version), "holders rebuild");

            GUILayoutDriver.Click("Down weight-gain");
            inspector.OnInspectorGUI();
            var names = profile.Effects.Select(e => e.effect).ToList();
            Assert.That(names.IndexOf("experimental-blend"), Is.EqualTo(names.IndexOf("weight-gain") - 1));

            UnityDouble.Editor.Type("threshold (m)", 20);
            inspector.OnInspectorGUI();
            Assert.That(profile.GetSetting("offset-correction", "threshold"), Is.EqualTo(20));
            inspector.OnInspectorGUI();
            Assert.That(UnityDouble.Editor.InspectorShown.Last(), Is.EqualTo("Error: profile 'xyz': effect 'offset-correction': setting 'threshold': threshold must lie in [0.001, 10], got 20."));
            Assert.That(UnityDouble.Editor.InspectorShown, Has.Member("Foldout: offset-correction (ObjectMotion)"));
            Assert.That(UnityDouble.Editor.InspectorShown, Has.Member(OffsetCorrection.Descriptor.Summary));
        }

        [TestCase(NamedProfiles.PaperName), TestCase(NamedProfiles.PaperExperimentName), TestCase(NamedProfiles.GainName), TestCase(NamedProfiles.XyzName)]
        public void APresetAssetExportsTheNamedProfilesFile(string preset)
        {
            var profile = PseudoHapticProfile.CreatePreset(preset);
            Assert.That(profile.ToJson(), Is.EqualTo(ProfileJson.Write(NamedProfiles.Get(preset))), "the same file as pseudohaptic profiles --show " + preset + " --json");
            var other = ScriptableObject.CreateInstance<PseudoHapticProfile>();
            other.FromJson(profile.ToJson(), preset + ".json");
            Assert.That(other.Build(), Is.SameAs(NamedProfiles.Get(preset)).Or.Property("Name").EqualTo(preset));
            Assert.That(other.ToJson(), Is.EqualTo(profile.ToJson()));
        }

        /// <summary>The fields of an asset saved before issue 33 for "paper-experiment" with break-away switched on, as its YAML
        /// held them (floats; values as the old CopyFrom wrote them).</summary>
        static string OldAssetFields() => "{" + string.Join(",", new[]
        {
            "\"_profileName\":\"old-experiment\"",
            "\"_trackingLossHold\":true", "\"_settleTime\":0.11", "\"_requireHighConfidence\":true",
            "\"_motionDeadband\":true", "\"_deadbandLagTime\":0.006", "\"_weightGain\":true", "\"_experimentalBlend\":true",
            "\"_heightDeceleration\":false", "\"_decelerationHeight\":0.125", "\"_decelerationMinFraction\":0.5",
            "\"_fasterMovesFurther\":true", "\"_fastExponent\":0.5", "\"_slowExponent\":1.5", "\"_restBand\":0.005", "\"_pauseTime\":0.16", "\"_paceSensitivity\":0.06",
            "\"_speedCap\":true", "\"_speedCapHeadroom\":2.5", "\"_loweringGuard\":true",
            "\"_offsetCorrection\":false", "\"_offsetThreshold\":0.2", "\"_offsetBand\":0.02",
            "\"_offsetRelaxation\":false", "\"_relaxationTimeConstant\":1.5", "\"_relaxationStillFraction\":0.1",
            "\"_floorClamp\":true", "\"_floor\":0", "\"_lateralInertia\":false", "\"_lateralTimeConstant\":0.3", "\"_lateralMaxOffset\":0.1",
            "\"_twoHands\":true", "\"_twoHandsShare\":0.5", "\"_breakAway\":true", "\"_breakAwayDistance\":0.4",
            "\"_maxGain\":3", "\"_maxHandSpeed\":10", "\"_maxFrameTime\":0.025", "\"_glideSpeed\":0.3",
            "\"_handDrawing\":1",
        }) + "}";

        /// <summary>
        /// An entry Unity kept empty (its effect's type went missing with its assembly) and one naming an effect nobody
        /// registered: each can be removed from the inspector (the empty one's button removed nothing: it was looked up by name).
        /// </summary>
        [Test]
        public void TheInspectorRemovesAnEmptyOrUnregisteredEntry()
        {
            var profile = PseudoHapticProfile.CreatePreset(NamedProfiles.GainName);
            var list = (System.Collections.Generic.List<ProfileEffect>)typeof(PseudoHapticProfile)
                .GetField("_effects", System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Instance)!.GetValue(profile)!;
            int count = list.Count;
            list.Insert(0, null);
            list.Add(new ProfileEffect { effect = "made-up" });
            var inspector = Inspector(profile);
            inspector.OnInspectorGUI();
            Assert.That(UnityDouble.Editor.InspectorShown, Has.Some.Contains("the profile is refused until it is registered or removed"));
            Assert.That(UnityDouble.Editor.InspectorShown, Has.Some.Contains("skipped when the profile is built"));
            GUILayoutDriver.Click("Remove (empty entry)");
            inspector.OnInspectorGUI();
            Assert.That(list, Has.None.Null, "the empty entry is gone");
            GUILayoutDriver.Click("Remove made-up");
            inspector.OnInspectorGUI();
            Assert.That(list, Has.Count.EqualTo(count));
            Assert.That(profile.TryBuild(out _, out string error), Is.True, error);
            Assert.That(profile.RemoveEffectAt(count), Is.False, "not an entry");
        }

        [Test]
        public void AnOldAssetsFlatFieldsAreReadOnceAndBecomeTheList()
        {
            var profile = ScriptableObject.CreateInstance<PseudoHapticProfile>(); // starts as "paper"
            JsonUtility.FromJsonOverwrite(OldAssetFields(), profile);
            var built = profile.Build();
            var expected = NamedProfiles.PaperExperiment.With(new BreakAway((double)0.4f));
            Assert.That(built.Effects.Select(e => e.Name), Is.EqualTo(expected.Effects.Select(e => e.Name)));
            Assert.That(built.Name, Is.EqualTo("old-experiment"));
            Assert.That(built.Find<BreakAway>().Distance, Is.EqualTo((double)0.4f));
            Assert.That(built.Find<MotionDeadband>().LagTime, Is.EqualTo((double)0.006f), "the old asset's float, as its Build passed it");
            Assert.That(built.Limits.MaxFrameTime, Is.EqualTo((double)0.025f));
            Assert.That(profile.HandDrawing, Is.EqualTo(HandDrawingMode.HandOnObject));

            // Read once: the old fields are marked read, so the next load (of what Unity saved) leaves the list alone.
            profile.RemoveEffect("break-away");
            JsonUtility.FromJsonOverwrite("{\"_profileName\":\"old-experiment\"}", profile);
            Assert.That(profile.IsEnabled<BreakAway>(), Is.False);
        }

        /// <summary>
        /// An old asset converted on load is saved once in the list format when the editor loads the scripts (Unity writes a
        /// ScriptableObject only when it is marked dirty: the conversion stayed in memory); a current asset is left alone.
        /// </summary>
        /// <summary>Whatever rewrites the asset's serialized state (an undo, a revert, a reimport) leaves no stale built profile.</summary>
        [Test]
        public void ADeserializedAssetBuildsWhatItNowHolds()
        {
            var profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            Assert.That(profile.Build().Has<OffsetCorrection>(), Is.True);
            int version = profile.Version;
            // What Unity's deserialization does (the double's JsonUtility has no [SerializeReference]): the field rewritten, then
            // the callback.
            var list = (System.Collections.Generic.List<ProfileEffect>)typeof(PseudoHapticProfile)
                .GetField("_effects", System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Instance)!.GetValue(profile)!;
            list.RemoveAll(e => e.effect == "offset-correction");
            ((ISerializationCallbackReceiver)profile).OnAfterDeserialize();
            Assert.That(profile.Build().Has<OffsetCorrection>(), Is.False, "built from what it holds now");
            Assert.That(profile.Version, Is.Not.EqualTo(version), "holders rebuild");
        }

        [Test]
        public void AnOldAssetConvertedOnLoadIsSavedOnceAsTheList()
        {
            var old = ScriptableObject.CreateInstance<PseudoHapticProfile>();
            JsonUtility.FromJsonOverwrite(OldAssetFields(), old);
            Assert.That(old.UpgradedUnsaved, Is.True);
            AssetDatabase.CreateAsset(old, "Assets/Old Experiment.asset");
            var current = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            AssetDatabase.CreateAsset(current, "Assets/Paper.asset");
            LogAssert.Expect(LogType.Log, new System.Text.RegularExpressions.Regex("1 profile asset"));
            Assert.That(Kosmos.PseudoHaptic.Editor.LegacyProfileUpgrade.SaveUpgraded(), Is.EqualTo(1));
            Assert.That(old.UpgradedUnsaved, Is.False);
            Assert.That(Kosmos.PseudoHaptic.Editor.LegacyProfileUpgrade.SaveUpgraded(), Is.Zero, "once");
        }

        [Test]
        public void AnEffectFromAnotherAssemblyIsBuiltExportedReadBackAndRun()
        {
            EffectRegistry.Register(Wobble.Descriptor);
            var profile = PseudoHapticProfile.CreatePreset(NamedProfiles.GainName);
            Assert.That(profile.AddEffect("wobble"), Is.True);
            profile.SetSetting("wobble", "height", 0.05);
            string json = profile.ToJson();
            Assert.That(json, Does.Contain("{ \"effect\": \"wobble\", \"height\": 0.05 }"));

            var back = ScriptableObject.CreateInstance<PseudoHapticProfile>();
            back.FromJson(json, "wobble.json");
            Assert.That(back.Build().Find<Wobble>().Height, Is.EqualTo(0.05));

            var solver = new WeightSolver(WeightModel.FromMass(0.045), back.Build(), 0.5);
            solver.BeginHold(1.0, 1.0);
            double y = solver.Step(new HandSample(1.0, true, true, 0.011), 0.011);
            Assert.That(y, Is.EqualTo(1.05).Within(1e-9), "the standard weight stays with the hand, raised by the effect");
        }

        /// <summary>An effect declared in this test assembly, not the package's.</summary>
        public sealed class Wobble : WeightEffect
        {
            public static readonly EffectDescriptor Descriptor = new EffectDescriptor("wobble", EffectStage.Position, typeof(Wobble), "a Unity test",
                "raises the object by a fixed height", s => new Wobble(s[0]),
                SettingDescriptor.Number<Wobble>("height", "m", 0.01, 0, 0.5, "how far", e => e.Height));

            public override string Name => Descriptor.Name;
            public override EffectStage Stage => Descriptor.Stage;
            public double Height { get; }
            public Wobble(double height) { Height = Descriptor.Settings[0].Check(height); }
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => frame.NewObjectY += Height;
        }
    }
}
