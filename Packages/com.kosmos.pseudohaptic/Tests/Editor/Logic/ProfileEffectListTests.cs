using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Issue 33, the profile asset's list, engine-free: presets round-trip, add in stage order, remove, move only
    /// within a stage, the Add Effect menu, an effect of another assembly, and the upgrade of an old asset's flat fields.</summary>
    public class ProfileEffectListTests
    {
        [Test]
        public void EveryNamedProfileAsAListBuildsTheSameProfile()
        {
            foreach (string name in NamedProfiles.Names)
            {
                var p = NamedProfiles.Get(name);
                var list = ProfileEffectList.FromProfile(p);
                var built = ProfileEffectList.Build(name, list, ProfileEffectList.Limits(ProfileEffectList.LimitValues(p.Limits)));
                Assert.That(ProfileJson.Write(built.WithHandFilter(p.HandFilter, name)), Is.EqualTo(ProfileJson.Write(p)), name);
            }
        }

        [Test]
        public void AddingKeepsTheStageOrderAndRefusesADuplicate()
        {
            var list = ProfileEffectList.FromProfile(NamedProfiles.Gain); // motion-deadband, weight-gain, floor-clamp
            Assert.That(ProfileEffectList.Add(list, "tracking-loss-hold"), Is.True);
            Assert.That(ProfileEffectList.Add(list, "offset-correction"), Is.True);
            Assert.That(ProfileEffectList.Add(list, "lateral-inertia"), Is.True);
            Assert.That(list.Select(e => e.effect), Is.EqualTo(new[] { "tracking-loss-hold", "motion-deadband", "weight-gain", "offset-correction", "floor-clamp", "lateral-inertia" }));
            Assert.That(ProfileEffectList.Add(list, "weight-gain"), Is.False);
            Assert.That(list.Count, Is.EqualTo(6));
            Assert.That(list[3].Get("threshold"), Is.EqualTo(0.2), "added at its declared default");
            var e = Assert.Catch<ArgumentException>(() => ProfileEffectList.Add(list, "heaviness"));
            Assert.That(e.Message, Does.Contain("heaviness").And.Contain("speed-cap"));
        }

        [Test]
        public void RemovingAnEffectRemovesItFromTheBuiltProfile()
        {
            var list = ProfileEffectList.FromProfile(NamedProfiles.Paper);
            Assert.That(ProfileEffectList.Remove(list, "offset-correction"), Is.True);
            Assert.That(ProfileEffectList.Remove(list, "offset-correction"), Is.False);
            var built = ProfileEffectList.Build("p", list, SolverLimits.Default);
            Assert.That(built.Has<OffsetCorrection>(), Is.False);
            Assert.That(built.Effects.Count, Is.EqualTo(NamedProfiles.Paper.Effects.Count - 1));
        }

        [Test]
        public void AnEffectMovesOnlyPastANeighbourOfItsStage()
        {
            var list = ProfileEffectList.FromProfile(NamedProfiles.Xyz);
            int gain = ProfileEffectList.IndexOf(list, "weight-gain"), blend = ProfileEffectList.IndexOf(list, "experimental-blend");
            Assert.That(blend, Is.EqualTo(gain + 1));
            Assert.That(ProfileEffectList.CanMove(list, gain, 1), Is.True, "two Gain effects");
            Assert.That(ProfileEffectList.Move(list, gain, 1), Is.True);
            Assert.That(list[gain].effect, Is.EqualTo("experimental-blend"));
            int first = 0; // tracking-loss-hold, the only Input effect
            Assert.That(ProfileEffectList.CanMove(list, first, -1), Is.False);
            Assert.That(ProfileEffectList.CanMove(list, first, 1), Is.False, "past a HandMotion effect: the stage decides");
            Assert.That(ProfileEffectList.Move(list, first, 1), Is.False);
            // Within Lift, the order is the order the effects run in: the built profile follows the list.
            int hd = ProfileEffectList.IndexOf(list, "height-deceleration");
            Assert.That(ProfileEffectList.Move(list, hd, 1), Is.True);
            var built = ProfileEffectList.Build("x", list, SolverLimits.Default);
            var lift = built.Effects.Where(e => e.Stage == EffectStage.Lift).Select(e => e.Name).ToArray();
            Assert.That(lift, Is.EqualTo(new[] { "faster-moves-further", "height-deceleration" }));
        }

        [Test]
        public void TheAddEffectMenuListsEveryRegisteredEffectWithItsSummaryAndWhichAreListed()
        {
            ScaledOffset.Register();
            var list = ProfileEffectList.FromProfile(NamedProfiles.Gain);
            var menu = ProfileEffectList.Menu(list);
            Assert.That(menu.Select(m => m.Key), Is.EqualTo(EffectRegistry.All));
            Assert.That(menu.Where(m => m.Value).Select(m => m.Key.Name), Is.EquivalentTo(new[] { "motion-deadband", "weight-gain", "floor-clamp" }));
            Assert.That(ProfileEffectList.MenuText(ScaledOffset.Descriptor), Is.EqualTo("ObjectMotion/scaled-offset — the weight's offset times a factor"));
            Assert.That(ProfileEffectList.MenuText(WeightGain.Descriptor), Does.Not.Contain("W_std/W").And.StartWith("Gain/weight-gain — "), "no '/' opens a submenu");
        }

        [Test]
        public void AnEffectOfAnotherAssemblyIsListedSetAndBuilt()
        {
            ScaledOffset.Register();
            var list = ProfileEffectList.FromProfile(NamedProfiles.Paper);
            Assert.That(ProfileEffectList.Add(list, "scaled-offset"), Is.True);
            list[ProfileEffectList.IndexOf(list, "scaled-offset")].Set("factor", 1.5);
            var built = ProfileEffectList.Build("p", list, SolverLimits.Default);
            Assert.That(built.Find<ScaledOffset>().Factor, Is.EqualTo(1.5));
            list[ProfileEffectList.IndexOf(list, "scaled-offset")].Set("factor", 9);
            var e = Assert.Catch<ArgumentException>(() => ProfileEffectList.Build("p", list, SolverLimits.Default));
            Assert.That(e.Message, Does.StartWith("effect 'scaled-offset': setting 'factor': factor must lie in [0, 4], got 9"));
        }

        [Test]
        public void AnEntryOfAnUnregisteredEffectOrSettingIsNamed()
        {
            var entry = new ProfileEffect { effect = "gone" };
            Assert.That(Assert.Catch<ArgumentException>(() => entry.Build()).Message, Does.Contain("'gone' is unknown"));
            var oc = ProfileEffect.Of(OffsetCorrection.Descriptor);
            Assert.That(Assert.Catch<ArgumentException>(() => oc.Set("treshold", 1)).Message, Does.Contain("offset-correction").And.Contain("treshold"));
            // A value the effect no longer declares is ignored; one it lacks takes its default.
            oc.settings.Add(new EffectSettingValue("retired", 3));
            oc.settings.RemoveAll(v => v.name == "band");
            Assert.That(((OffsetCorrection)oc.Build()).Band, Is.EqualTo(0.02));
        }

        // Issue 35 (logic-session survivors): what the profile inspector and the profile asset rely on of an entry and the list.

        [Test]
        public void AnEntryKeepsTheValuesItWasMadeWithAndShowsItsSettingsWhenAdded()
        {
            var oc = ProfileEffect.Of(OffsetCorrection.Descriptor.DefaultSettings().Set("band", 0.05).Set("maxScale", 2));
            Assert.That(oc.Get("band"), Is.EqualTo(0.05));
            Assert.That(((OffsetCorrection)oc.Build()).MaxScale, Is.EqualTo(2));
            Assert.That(oc.Get("threshold"), Is.EqualTo(0.2), "the others at their defaults");
            // A preset as a list keeps a value that is not the default.
            var p = new WeightProfile("p", new WeightEffect[] { new OffsetCorrection(0.3, 0.04, 0.1, 0.75, 1.3) }, SolverLimits.Default);
            Assert.That(ProfileEffectList.FromProfile(p)[0].Get("band"), Is.EqualTo(0.04));
            // An effect just added to the inspector's list shows its settings (unfolded), so the user sees what was added.
            var list = ProfileEffectList.FromProfile(NamedProfiles.Gain);
            ProfileEffectList.Add(list, "offset-correction");
            Assert.That(list[ProfileEffectList.IndexOf(list, "offset-correction")].expanded, Is.True);
            Assert.That(new ProfileEffect().expanded, Is.True);
        }

        [Test]
        public void GetAndSetReadAndWriteAnySettingAndNameTheEffectAndTheSettingWhenThereIsNone()
        {
            var oc = ProfileEffect.Of(OffsetCorrection.Descriptor);
            Assert.That(oc.Get("band"), Is.EqualTo(0.02), "a setting after the first");
            var get = Assert.Catch<ArgumentException>(() => oc.Get("treshold"));
            Assert.That(get.ParamName, Is.EqualTo("setting"));
            Assert.That(get.Message, Does.Contain("'offset-correction'").And.Contain("'treshold'"), "both names, quoted");
            var set = Assert.Catch<ArgumentException>(() => oc.Set("treshold", 1));
            Assert.That(set.Message, Does.Contain("'offset-correction'").And.Contain("'treshold'"), "both names, quoted");
            // A setting the entry lacks (an asset saved before the effect had it) is added; one it has is changed in place:
            // however often the inspector sets a value, the asset holds it once.
            oc.settings.RemoveAll(v => v.name == "band");
            oc.Set("band", 0.05);
            Assert.That(oc.Get("band"), Is.EqualTo(0.05));
            foreach (double v in new[] { 0.1, 0.5, 0.3 }) oc.Set("threshold", v);
            Assert.That(oc.Get("threshold"), Is.EqualTo(0.3));
            Assert.That(oc.settings.Select(v => v.name), Is.EquivalentTo(OffsetCorrection.Descriptor.Settings.Select(s => s.Name)), "one value per setting");
        }

        [Test]
        public void AnEmptySlotInAnEntrysValuesIsSkipped()
        {
            var oc = ProfileEffect.Of(OffsetCorrection.Descriptor);
            oc.settings.Insert(0, null);
            oc.Set("band", 0.05);
            Assert.That(((OffsetCorrection)oc.Build()).Band, Is.EqualTo(0.05));
            Assert.That(oc.Get("threshold"), Is.EqualTo(0.2));
        }

        [Test]
        public void AnUnregisteredEffectIsNamedWithTheEffectsThatAreKnown()
        {
            string known = "known effects: " + string.Join(", ", EffectRegistry.All.Select(d => d.Name)) + "."; // the sentence ends there
            var entry = new ProfileEffect { effect = "gone" };
            Assert.That(Assert.Catch<ArgumentException>(() => entry.Values()).Message, Does.Contain("'gone' is unknown").And.Contain(known));
            var list = ProfileEffectList.FromProfile(NamedProfiles.Gain);
            var add = Assert.Catch<ArgumentException>(() => ProfileEffectList.Add(list, entry));
            Assert.That(add.Message, Does.Contain("'gone' is unknown").And.Contain(known));
            Assert.That(list.Count, Is.EqualTo(NamedProfiles.Gain.Effects.Count), "nothing added");
        }

        [Test]
        public void LimitsRoundTripThroughTheirValuesAndABadOneIsNamedOnOneLine()
        {
            var limits = new SolverLimits(maxGain: 5, maxHandSpeed: 8, maxFrameTime: 0.05, glideSpeed: 0.4, workspaceRadius: 6);
            var values = ProfileEffectList.LimitValues(limits);
            Assert.That(values.Select(v => v.name), Is.EqualTo(SolverLimits.Settings.Select(s => s.Name)));
            var back = ProfileEffectList.Limits(values);
            Assert.That(new[] { back.MaxGain, back.MaxHandSpeed, back.MaxFrameTime, back.GlideSpeed, back.WorkspaceRadius },
                Is.EqualTo(new[] { 5, 8, 0.05, 0.4, 6 }));
            // The same message a profile file's bad limit gets (ProfileJson): the setting, then the one-line reason.
            values[0].value = 0.5;
            var e = Assert.Throws<EffectSettingException>(() => ProfileEffectList.Limits(values));
            Assert.That(e.ParamName, Is.EqualTo("maxGain"));
            Assert.That(e.Message, Is.EqualTo("limits: setting 'maxGain': maxGain must lie in [1, 100], got 0.5."));
        }

        [TestCase("maxGain must lie in [1, 100], got 0.5. (Parameter 'maxGain')")]                        // .NET
        [TestCase("maxGain must lie in [1, 100], got 0.5.\nParameter name: maxGain\nActual value was 0.5.")] // Mono: Unity's runtime
        [TestCase("maxGain must lie in [1, 100], got 0.5.\r\nParameter name: maxGain")]
        [TestCase("maxGain must lie in [1, 100], got 0.5.")]
        public void ALimitsMessageIsItsFirstLineWithoutTheParameterTheRuntimeAdds(string message)
        {
            // The inspector and the JSON errors show one line; in Unity (Mono) the parameter comes on lines of its own.
            Assert.That(ProfileEffectList.FirstLine(message), Is.EqualTo("maxGain must lie in [1, 100], got 0.5."));
            Assert.That(ProfileEffectList.FirstLine("(Parameter 'x')"), Is.EqualTo("(Parameter 'x')"), "a message that is only a parenthesis keeps it");
        }

        [Test]
        public void AddingToAStageThatHasEffectsPutsTheNewOneLastOfItsStage()
        {
            var list = ProfileEffectList.FromProfile(NamedProfiles.Gain); // motion-deadband, weight-gain, floor-clamp
            Assert.That(ProfileEffectList.Add(list, "experimental-blend"), Is.True);
            Assert.That(list.Select(e => e.effect), Is.EqualTo(new[] { "motion-deadband", "weight-gain", "experimental-blend", "floor-clamp" }));
            Assert.That(ProfileEffectList.Add(list, "motion-deadband"), Is.False, "the first entry is there already");
            Assert.That(list.Count, Is.EqualTo(4));
            Assert.That(ProfileEffectList.Remove(list, "motion-deadband"), Is.True, "the first entry can be removed");
            Assert.That(list.Select(e => e.effect), Is.EqualTo(new[] { "weight-gain", "experimental-blend", "floor-clamp" }));
        }

        [Test]
        public void OnlyAStepOfOneToANeighbourInsideTheListCanMove()
        {
            var list = new List<ProfileEffect>
            {
                ProfileEffect.Of(WeightGain.Descriptor), ProfileEffect.Of(ExperimentalBlend.Descriptor), new ProfileEffect { effect = "gone" },
            };
            Assert.That(ProfileEffectList.CanMove(list, 0, 1), Is.True, "the first entry moves down");
            Assert.That(ProfileEffectList.CanMove(list, 1, -1), Is.True, "to the first place");
            Assert.That(ProfileEffectList.CanMove(list, 0, 0), Is.False, "no step");
            Assert.That(ProfileEffectList.Move(list, 0, 0), Is.False);
            Assert.That(ProfileEffectList.CanMove(list, 0, 2), Is.False, "more than one step");
            Assert.That(ProfileEffectList.CanMove(list, 0, -1), Is.False, "above the first");
            Assert.That(ProfileEffectList.CanMove(list, -1, 1), Is.False, "an index before the list");
            Assert.That(ProfileEffectList.CanMove(list, list.Count, -1), Is.False, "an index past the list");
            Assert.That(ProfileEffectList.CanMove(list, list.Count - 1, 1), Is.False, "below the last");
            // An entry of an effect not registered (its assembly removed) moves nowhere and nothing moves past it.
            Assert.That(ProfileEffectList.CanMove(list, 1, 1), Is.False);
            Assert.That(ProfileEffectList.CanMove(list, 2, -1), Is.False);
            Assert.That(list.Select(e => e.effect), Is.EqualTo(new[] { "weight-gain", "experimental-blend", "gone" }), "nothing moved");
        }

        /// <summary>The fields an old asset saved for a named profile, as its CopyFrom wrote them (floats).</summary>
        static LegacyProfileFields OldAsset(WeightProfile p)
        {
            var tl = p.Find<TrackingLossHold>() ?? new TrackingLossHold();
            var fm = p.Find<FasterMovesFurther>() ?? new FasterMovesFurther();
            var hd = p.Find<HeightDeceleration>() ?? new HeightDeceleration();
            var oc = p.Find<OffsetCorrection>() ?? new OffsetCorrection();
            var rl = p.Find<OffsetRelaxation>() ?? new OffsetRelaxation();
            var li = p.Find<LateralInertia>() ?? new LateralInertia();
            return new LegacyProfileFields
            {
                trackingLossHold = p.Has<TrackingLossHold>(), settleTime = (float)tl.SettleTime, requireHighConfidence = tl.RequireHighConfidence,
                motionDeadband = p.Has<MotionDeadband>(), deadbandLagTime = (float)(p.Find<MotionDeadband>() ?? new MotionDeadband()).LagTime,
                weightGain = p.Has<WeightGain>(), experimentalBlend = p.Has<ExperimentalBlend>(),
                heightDeceleration = p.Has<HeightDeceleration>(), decelerationHeight = (float)hd.Height, decelerationMinFraction = (float)hd.MinFraction,
                fasterMovesFurther = p.Has<FasterMovesFurther>(), fastExponent = (float)fm.FastExponent, slowExponent = (float)fm.SlowExponent,
                restBand = (float)fm.RestBand, pauseTime = (float)fm.PauseTime, paceSensitivity = (float)fm.Sensitivity,
                speedCap = p.Has<SpeedCap>(), speedCapHeadroom = (float)(p.Find<SpeedCap>() ?? new SpeedCap()).Headroom,
                loweringGuard = p.Has<LoweringGuard>(), offsetCorrection = p.Has<OffsetCorrection>(), offsetThreshold = (float)oc.Threshold, offsetBand = (float)oc.Band,
                offsetRelaxation = p.Has<OffsetRelaxation>(), relaxationTimeConstant = (float)rl.TimeConstant, relaxationStillFraction = (float)rl.StillFraction,
                floorClamp = p.Has<FloorClamp>(), floor = (float)(p.Find<FloorClamp>() ?? new FloorClamp()).Floor,
                lateralInertia = p.Has<LateralInertia>(), lateralTimeConstant = (float)li.TimeConstant, lateralMaxOffset = (float)li.MaxOffset,
                twoHands = p.Has<TwoHands>(), twoHandsShare = (float)(p.Find<TwoHands>() ?? new TwoHands()).Share,
                breakAway = false, breakAwayDistance = 0.25f,
                maxGain = (float)p.Limits.MaxGain, maxHandSpeed = (float)p.Limits.MaxHandSpeed, maxFrameTime = (float)p.Limits.MaxFrameTime, glideSpeed = (float)p.Limits.GlideSpeed,
            };
        }

        [Test]
        public void AnOldAssetsFieldsBecomeTheListItBuiltValueForValue()
        {
            foreach (string name in NamedProfiles.Names)
            {
                var p = NamedProfiles.Get(name);
                var old = OldAsset(p);
                var upgraded = ProfileEffectList.Build(name, old.Effects(), ProfileEffectList.Limits(old.Limits()));
                Assert.That(upgraded.Effects.Select(e => e.Name), Is.EqualTo(p.Effects.Select(e => e.Name)), name);
                // Every value is the old asset's float, as the old Build passed it to the core.
                foreach (var e in upgraded.Effects)
                {
                    var d = EffectRegistry.Of(e);
                    var now = d.SettingsOf(e);
                    var core = d.SettingsOf(p.Effects.Single(x => x.Name == e.Name));
                    for (int i = 0; i < d.Settings.Count; i++)
                    {
                        // The old asset stored only these; the rest were the core's defaults (jitterSpan, perDoubling, …, slack).
                        bool stored = !(d.Name == "motion-deadband" && i == 1) && !(d.Name == "offset-correction" && i >= 2) && d.Name != "lowering-guard";
                        double expected = d.Settings[i].Kind == SettingKind.Boolean || !stored ? core[i] : (double)(float)core[i];
                        Assert.That(now[i], Is.EqualTo(expected), name + ": " + d.Name + "." + d.Settings[i].Name);
                    }
                }
                Assert.That(upgraded.Limits.MaxFrameTime, Is.EqualTo((double)(float)p.Limits.MaxFrameTime));
                Assert.That(upgraded.Limits.WorkspaceRadius, Is.EqualTo(SolverLimits.DefaultWorkspaceRadius));
            }
        }

        [Test]
        public void AnOldAssetWithBreakAwayAndRelaxationOnKeepsThem()
        {
            var old = OldAsset(NamedProfiles.Xyz);
            old.breakAway = true;
            old.breakAwayDistance = 0.4f;
            old.offsetRelaxation = true;
            old.relaxationTimeConstant = 2f;
            var p = ProfileEffectList.Build("old", old.Effects(), ProfileEffectList.Limits(old.Limits()));
            Assert.That(p.Find<BreakAway>().Distance, Is.EqualTo((double)0.4f));
            Assert.That(p.Find<OffsetRelaxation>().TimeConstant, Is.EqualTo(2));
            old.weightGain = false;
            Assert.That(ProfileEffectList.Build("old", old.Effects(), SolverLimits.Default).Has<WeightGain>(), Is.False, "a switch that was off lists nothing");
        }
    }
}
