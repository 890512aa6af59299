using System;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The profile file's reader and writer (<see cref="ProfileJson"/>), rule by rule: every error a hand-edited file can
    /// meet, with its exact message and line (a researcher reads these messages, and the tool's tests see only a few), the
    /// JSON the reader accepts (escapes, a byte-order mark, Windows line ends, nesting), and what the writer refuses.
    /// </summary>
    public class ProfileFileReaderTests
    {
        const string Head = "{\"format\":1,\"name\":\"x\",\"effects\":[]";

        static ProfileFormatException Refused(string json)
            => Assert.Throws<ProfileFormatException>(() => ProfileJson.Read(json, "p.json"));

        static void RefusedAs(string json, int line, string message)
        {
            var e = Refused(json);
            Assert.That(e.Message, Is.EqualTo("p.json:" + line + ": " + message), json);
            Assert.That(e.Line, Is.EqualTo(line), json);
            Assert.That(e.File, Is.EqualTo("p.json"), json);
        }

        // ---- the profile's keys -------------------------------------------------------------------------------------

        [Test]
        public void TheProfileIsAnObjectWithFormatNameAndEffects()
        {
            RefusedAs("[1]", 1, "a profile file is a JSON object");
            RefusedAs("{}", 1, "format: missing (write \"format\": 1)");
            RefusedAs("{\"format\":1,\"effects\":[]}", 1, "name: missing");
            RefusedAs("{\"format\":1,\"name\":\"x\"}", 1, "effects: missing");
            RefusedAs("{\n\"format\":1,\n\"name\":\"\",\n\"effects\":[]}", 3, "name: must be a non-empty string");
            RefusedAs("{\n\"format\":1,\n\"name\":\" \",\n\"effects\":[]}", 3, "name: must be a non-empty string");
            RefusedAs("{\n\"format\":1,\n\"name\":7,\n\"effects\":[]}", 3, "name: must be a non-empty string");
            RefusedAs("{\"format\":1,\"name\":\"x\",\n\"effects\":{}}", 2, "effects: must be a list of effects");
            RefusedAs(Head + ",\n\"colour\":3}", 2, "unknown key 'colour'; a profile has format, name, effects, limits, handFilter");
            // The keys may come in any order; an empty list is a profile without effects.
            var p = ProfileJson.Read("{\"effects\":[],\"name\":\"bare\",\"format\":1}", "p.json");
            Assert.That(p.Name, Is.EqualTo("bare"));
            Assert.That(p.Effects, Is.Empty);
            Assert.That(p.HandFilter, Is.Null);
            Assert.That(p.Limits.MaxGain, Is.EqualTo(SolverLimits.Default.MaxGain));
        }

        [TestCase("\"1\"", "\"1\"")]
        [TestCase("2", "2")]
        [TestCase("1.5", "1.5")]
        [TestCase("null", "null")]
        [TestCase("true", "true")]
        [TestCase("false", "false")]
        [TestCase("[1]", "a list")]
        [TestCase("{}", "an object")]
        public void AWrongFormatIsShownAsWritten(string value, string shown)
            => RefusedAs("{\"name\":\"x\",\"effects\":[],\n\"format\": " + value + "}", 2, "format: this version reads format 1, got " + shown);

        [Test]
        public void TheHandFilterIsTheOneSecondAverageOrNothing()
        {
            var none = ProfileJson.Read(Head + ",\"handFilter\":null}", "p.json");
            Assert.That(none.HandFilter, Is.Null);
            var avg = ProfileJson.Read(Head + ",\"handFilter\":\"one-second-average\"}", "p.json");
            Assert.That(avg.HandFilter, Is.InstanceOf<OneSecondAverage>());
            Assert.That(((OneSecondAverage)avg.HandFilter).Window, Is.EqualTo(1.0));
            RefusedAs(Head + ",\n\"handFilter\":\"exponential\"}", 2, "handFilter: must be \"one-second-average\" or null, got \"exponential\"");
            RefusedAs(Head + ",\n\"handFilter\":1}", 2, "handFilter: must be \"one-second-average\" or null, got 1");
        }

        // ---- effects ------------------------------------------------------------------------------------------------

        [Test]
        public void AnEffectIsAnObjectNamingARegisteredEffectOnce()
        {
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[\n3]}", 2, "effects: each effect is an object with \"effect\": NAME and its settings");
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[\n{\"threshold\":0.1}]}", 2, "effects: an effect without \"effect\": NAME");
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[\n{\"effect\":3}]}", 2, "effects: an effect without \"effect\": NAME");
            string known = string.Join(", ", EffectRegistry.All.Select(d => d.Name));
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\n\"effect\":\"heavy\"}]}", 2, "effect 'heavy' is unknown; known effects: " + known);
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"floor-clamp\"},\n{\"effect\":\"floor-clamp\"}]}", 2,
                "effect 'floor-clamp' is listed twice");
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"offset-correction\",\n\"treshold\":0.1}]}", 2,
                "effect 'offset-correction': unknown setting 'treshold'; its settings: threshold, band, perDoubling, minScale, maxScale");
            // The name may come after the settings.
            var p = ProfileJson.Read("{\"format\":1,\"name\":\"x\",\"effects\":[{\"threshold\":0.2,\"effect\":\"offset-correction\"}]}", "p.json");
            Assert.That(((OffsetCorrection)p.Effects[0]).Threshold, Is.EqualTo(0.2));
        }

        [Test]
        public void AnInvalidSettingIsReportedOnItsOwnLineAndATypeMismatchNamesTheType()
        {
            // The bad value on line 3; a valid setting after it (line 4) must not take the blame.
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"offset-correction\",\n\n\"threshold\":20,\n\"band\":0.01}]}", 3,
                "effect 'offset-correction': setting 'threshold': threshold must lie in [0.001, 10], got 20");
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"tracking-loss-hold\",\n\"requireHighConfidence\":1}]}", 2,
                "effect 'tracking-loss-hold': setting 'requireHighConfidence': must be true or false, got 1");
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"tracking-loss-hold\",\n\"settleTime\":true}]}", 2,
                "effect 'tracking-loss-hold': setting 'settleTime': must be a number (s), got true");
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"offset-correction\",\n\"threshold\":null}]}", 2,
                "effect 'offset-correction': setting 'threshold': must be a number (m), got null");
            var p = ProfileJson.Read("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"tracking-loss-hold\",\"requireHighConfidence\":false}]}", "p.json");
            Assert.That(((TrackingLossHold)p.Effects[0]).RequireHighConfidence, Is.False);
        }

        [Test]
        public void AnEffectsOwnRuleWithoutASettingIsReportedAtItsLastSetting()
        {
            // The factory's ArgumentException names no setting: the line is the effect's last setting's (or the effect's own).
            EffectRegistry.Register(ReaderRuleCheck.Descriptor);
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"reader-rule-check\",\n\n\"n\":3,\n\"m\":1}]}", 4,
                "effect 'reader-rule-check': n + m must not be 4");
            RefusedAs("{\"format\":1,\"name\":\"x\",\"effects\":[\n{\"effect\":\"reader-rule-check\",\"m\":3}]}", 2,
                "effect 'reader-rule-check': n + m must not be 4");
            var p = ProfileJson.Read("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"reader-rule-check\",\"n\":2}]}", "p.json");
            Assert.That(p.Effects[0], Is.InstanceOf<ReaderRuleCheck>());
        }

        /// <summary>An effect with a rule of its own over two settings (n + m must not be 4, say), whose factory refuses
        /// without naming a setting.</summary>
        sealed class ReaderRuleCheck : WeightEffect
        {
            public static readonly EffectDescriptor Descriptor = new EffectDescriptor("reader-rule-check", EffectStage.ObjectMotion,
                typeof(ReaderRuleCheck), "a test", "refuses n + m = 4",
                s => s[0] + s[1] == 4 ? throw new ArgumentException("n + m must not be 4") : new ReaderRuleCheck(),
                SettingDescriptor.Number<ReaderRuleCheck>("n", "", 1, 0, 10, "a number", e => 1),
                SettingDescriptor.Number<ReaderRuleCheck>("m", "", 0, 0, 10, "a number", e => 0));

            public override string Name => Descriptor.Name;
            public override EffectStage Stage => Descriptor.Stage;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
        }

        // ---- limits ---------------------------------------------------------------------------------------------------

        [Test]
        public void LimitsAreAnObjectOfKnownSettingsEachChecked()
        {
            RefusedAs(Head + ",\n\"limits\":[]}", 2, "limits: must be an object");
            RefusedAs(Head + ",\"limits\":{\n\"maxgain\":3}}", 2, "limits: unknown setting 'maxgain'");
            RefusedAs(Head + ",\"limits\":{\"maxGain\":3,\n\"maxHandSpeed\":0}}", 2,
                "limits: setting 'maxHandSpeed': maxHandSpeed must be a finite number greater than 0, got 0");
            RefusedAs(Head + ",\"limits\":{\n\"maxGain\":true}}", 2, "limits: setting 'maxGain': must be a number (), got true");
            var p = ProfileJson.Read(Head + ",\"limits\":{\"glideSpeed\":0.5,\"maxGain\":4}}", "p.json");
            Assert.That(p.Limits.GlideSpeed, Is.EqualTo(0.5));
            Assert.That(p.Limits.MaxGain, Is.EqualTo(4.0));
            Assert.That(p.Limits.MaxHandSpeed, Is.EqualTo(SolverLimits.Default.MaxHandSpeed), "a limit left out takes its default");
            Assert.That(p.Limits.MaxFrameTime, Is.EqualTo(SolverLimits.Default.MaxFrameTime));
            Assert.That(p.Limits.WorkspaceRadius, Is.EqualTo(SolverLimits.Default.WorkspaceRadius));
        }

        // ---- JSON ------------------------------------------------------------------------------------------------------

        [TestCase("{ x: 1 }", 1, "expected a quoted key")]
        [TestCase("{\"a\":1,\n}", 2, "expected a quoted key")]
        [TestCase("{", 1, "expected a quoted key")]
        [TestCase("{ \n", 2, "expected a quoted key")]
        [TestCase("{\"a\":1,", 1, "expected a quoted key")]
        [TestCase("{\"a\":\"\\u0041", 1, "a string that does not end on its line")]
        [TestCase("{\"a\":1,\n\"a\":2}", 2, "key 'a' given twice")]
        [TestCase("{\"a\"\n1}", 2, "expected ':' after \"a\"")]
        [TestCase("{\"a\"", 1, "expected ':' after \"a\"")]
        [TestCase("{\"a\":1\n\"b\":2}", 2, "expected ',' or '}'")]
        [TestCase("{\"a\":1", 1, "expected ',' or '}'")]
        [TestCase("{\"a\":[1\n2]}", 2, "expected ',' or ']'")]
        [TestCase("{\"a\":[1", 1, "expected ',' or ']'")]
        [TestCase("{\"a\":\n", 2, "the text ends where a value was expected")]
        [TestCase("", 1, "the text ends where a value was expected")]
        [TestCase("{\"a\":tru}", 1, "a value that is not a number, a string, true, false, null, a list or an object")]
        [TestCase("{\"a\":-}", 1, "a value that is not a number, a string, true, false, null, a list or an object")]
        [TestCase("{\"a\":1e999}", 1, "a value that is not a number, a string, true, false, null, a list or an object")]
        [TestCase("{\"a\":.}", 1, "a value that is not a number, a string, true, false, null, a list or an object")]
        [TestCase("{\"a\":\"b\nc\"}", 1, "a string that does not end on its line")]
        [TestCase("{\"a\":\"b", 1, "a string that does not end on its line")]
        [TestCase("{\"a\":\"b\\", 1, "a string that does not end")]
        [TestCase("{\"a\":\"\\x\"}", 1, "a bad escape \\x")]
        [TestCase("{\"a\":\"\\u12G4\"}", 1, "a bad \\u escape")]
        [TestCase("{\"a\":\"\\u12", 1, "a bad \\u escape")]
        [TestCase("{}\n{}", 2, "text after the profile's closing brace")]
        [TestCase("{} x", 1, "text after the profile's closing brace")]
        [TestCase("\r\n\t{\r\n\"a\" 1}", 3, "expected ':' after \"a\"")]
        public void NotJsonIsRefusedWithTheLineItStopsOn(string json, int line, string what)
            => RefusedAs(json, line, "not valid JSON: " + what);

        [Test]
        public void NestingIsRefusedBeyond64Levels()
        {
            // The profile object is level 0; "x" holds 64 nested lists: read (then refused as an unknown key); 65: not JSON.
            string Nested(int lists) => "{\"x\":" + new string('[', lists) + new string(']', lists) + "}";
            RefusedAs(Nested(64), 1, "unknown key 'x'; a profile has format, name, effects, limits, handFilter");
            RefusedAs(Nested(65), 1, "not valid JSON: nested too deeply");
        }

        [Test]
        public void EmptyListsAndObjectsMayHoldSpaceAndLineBreaks()
        {
            var p = ProfileJson.Read("{ \"format\": 1, \"name\": \"x\", \"effects\": [ \n\t], \"limits\": {\r\n } }", "p.json");
            Assert.That(p.Effects, Is.Empty);
            Assert.That(p.Limits.MaxGain, Is.EqualTo(SolverLimits.Default.MaxGain));
            RefusedAs("{ \"format\": 1, \"name\": \"x\", \"effects\": [ \n ], \"colour\": { } }", 2,
                "unknown key 'colour'; a profile has format, name, effects, limits, handFilter");
        }

        [Test]
        public void StringsReadEveryEscapeAndTheWriterWritesThemBack()
        {
            var p = ProfileJson.Read("\uFEFF{\"format\":1,\"effects\":[],\"name\":\"q\\\" b\\\\ s\\/ n\\n t\\t r\\r b\\b f\\f u\\u0041\\u00e9\"}", "p.json");
            Assert.That(p.Name, Is.EqualTo("q\" b\\ s/ n\n t\t r\r b\b f\f uAé"));
            string written = ProfileJson.Write(p);
            // Quotes and backslashes escaped, control characters as \u00XX, the rest (a slash, é) as it is.
            StringAssert.Contains("\"name\": \"q\\\" b\\\\ s/ n\\u000a t\\u0009 r\\u000d b\\u0008 f\\u000c uAé\"", written);
            Assert.That(ProfileJson.Read(written, "again.json").Name, Is.EqualTo(p.Name));
        }

        [Test]
        public void NumbersReadAsJsonWritesThem()
        {
            var p = ProfileJson.Read("{\"format\":1,\"name\":\"x\",\"effects\":[{\"effect\":\"floor-clamp\",\"floor\":-1.25E-1},"
                + "{\"effect\":\"offset-correction\",\"threshold\":2e-2,\"band\":+0.5}]}", "p.json");
            Assert.That(p.Find<FloorClamp>().Floor, Is.EqualTo(-0.125));
            Assert.That(p.Find<OffsetCorrection>().Threshold, Is.EqualTo(0.02));
            Assert.That(p.Find<OffsetCorrection>().Band, Is.EqualTo(0.5));
        }

        [Test]
        public void TheSourceNamesEveryMessageAndAnEmptyOneIsCalledProfile()
        {
            Assert.That(Assert.Throws<ProfileFormatException>(() => ProfileJson.Read("[]", "")).Message, Is.EqualTo("profile:1: a profile file is a JSON object"));
            Assert.That(Assert.Throws<ProfileFormatException>(() => ProfileJson.Read("[]", null)).File, Is.EqualTo("profile"));
            Assert.Throws<ArgumentNullException>(() => ProfileJson.Read(null, "p.json"));
        }

        // ---- the writer ------------------------------------------------------------------------------------------------

        [Test]
        public void TheWriterWritesTheOneSecondAverageAndRefusesAnyOtherFilter()
        {
            string paperLiteral = ProfileJson.Write(NamedProfiles.Get(NamedProfiles.PaperLiteralName));
            StringAssert.EndsWith(",\n  \"handFilter\": \"one-second-average\"\n}\n", paperLiteral);
            StringAssert.DoesNotContain("handFilter", ProfileJson.Write(NamedProfiles.Paper));
            foreach (var filter in new IHandFilter[] { new ExponentialSmoothing(), new OneSecondAverage(0.5), new OneSecondAverage(1.0, 512) })
            {
                var profile = new WeightProfile("filtered", new WeightEffect[0], null, filter);
                var e = Assert.Throws<ArgumentException>(() => ProfileJson.Write(profile));
                Assert.That(e.ParamName, Is.EqualTo("profile"));
                StringAssert.StartsWith("profile 'filtered': its hand filter '" + filter.Name + "' cannot be written to a profile file (only 'one-second-average').", e.Message);
            }
            Assert.Throws<ArgumentNullException>(() => ProfileJson.Write(null));
        }

        [Test]
        public void AProfileWithoutEffectsIsWrittenAsAnEmptyList()
        {
            string written = ProfileJson.Write(new WeightProfile("bare", new WeightEffect[0]));
            StringAssert.StartsWith("{\n  \"format\": 1,\n  \"name\": \"bare\",\n  \"effects\": [],\n  \"limits\": { \"maxGain\": 3, \"maxHandSpeed\": 10, ", written);
            StringAssert.EndsWith(" }\n}\n", written);
            Assert.That(ProfileJson.Read(written, "bare.json").Effects, Is.Empty);
        }

        [Test]
        public void EffectsAreWrittenOnePerLineInTheProfilesOrder()
        {
            var profile = new WeightProfile("two", new WeightEffect[] { new FloorClamp(0.25), new TrackingLossHold() });
            string written = ProfileJson.Write(profile);
            StringAssert.Contains("\"effects\": [\n    { \"effect\": \"tracking-loss-hold\", \"settleTime\": ", written);
            StringAssert.Contains(" },\n    { \"effect\": \"floor-clamp\", \"floor\": 0.25 }\n  ],\n", written);
            Assert.That(ProfileJson.Read(written, "two.json").Effects.Select(e => e.Name), Is.EqualTo(profile.Effects.Select(e => e.Name)));
        }
    }
}
