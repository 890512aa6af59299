using System;
using System.Linq;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// What a scene's or a test's own effect meets when it declares itself (<see cref="SettingDescriptor"/>,
    /// <see cref="EffectDescriptor"/>, <see cref="EffectSettings"/>, <see cref="EffectRegistry"/>): each mistake refused with
    /// a message that names it, and the ranges written as the docs and the Unity list show them. The package's own effects
    /// are tested against their declarations in <see cref="EffectDescriptorTests"/>.
    /// </summary>
    public class DescriptorContractTests
    {
        sealed class Probe : WeightEffect
        {
            public static readonly EffectDescriptor Descriptor = new EffectDescriptor("descriptor-probe", EffectStage.ObjectMotion, typeof(Probe),
                "a test", "does nothing", s => new Probe(s[0], s.Flag(1)),
                SettingDescriptor.Number<Probe>("level", "m", 0.5, 0, 2, "a level", e => e.Level),
                SettingDescriptor.Boolean<Probe>("on", true, "a switch", e => e.On));

            public Probe(double level = 0.5, bool on = true) { Level = level; On = on; }
            public double Level { get; }
            public bool On { get; }
            public override string Name => "descriptor-probe";
            public override EffectStage Stage => EffectStage.ObjectMotion;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
        }

        /// <summary>Never registered.</summary>
        sealed class Unregistered : WeightEffect
        {
            public override string Name => "unregistered";
            public override EffectStage Stage => EffectStage.Position;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
        }

        static SettingDescriptor Level(double min, double max, double @default = 1) => SettingDescriptor.Number<Probe>("level", "m", @default, min, max, "", e => e.Level);

        // ---- settings -------------------------------------------------------------------------------------------------

        [Test]
        public void EachKindOfRangeIsWrittenAsTheDocsWriteIt()
        {
            Assert.That(SettingDescriptor.Boolean<Probe>("on", false, "", e => e.On).RangeText, Is.EqualTo("true/false"));
            Assert.That(SettingDescriptor.Positive<Probe>("p", "s", 1, "", e => 1).RangeText, Is.EqualTo("> 0"));
            Assert.That(SettingDescriptor.Positive<Probe>("p", "s", 1, "", e => 1, max: 2.5).RangeText, Is.EqualTo("(0, 2.5]"));
            Assert.That(Level(double.NegativeInfinity, double.PositiveInfinity).RangeText, Is.EqualTo("any finite"));
            Assert.That(Level(0.001, 10).RangeText, Is.EqualTo("[0.001, 10]"));
            Assert.That(Level(double.NegativeInfinity, 10).RangeText, Is.EqualTo("<= 10"));
            Assert.That(Level(-1, double.PositiveInfinity).RangeText, Is.EqualTo(">= -1"));
        }

        [Test]
        public void APositiveSettingWithACeilingTakesValuesAboveZeroUpToIt()
        {
            var p = SettingDescriptor.Positive<Probe>("p", "s", 1, "", e => 1, max: 2.5);
            Assert.That(p.MinExclusive, Is.True);
            Assert.That(p.Check(2.5), Is.EqualTo(2.5));
            Assert.That(p.Check(double.Epsilon), Is.EqualTo(double.Epsilon));
            foreach (double bad in new[] { 0.0, -1, 2.5000000000000004, double.NaN, double.PositiveInfinity, double.NegativeInfinity })
            {
                var e = Assert.Throws<ArgumentOutOfRangeException>(() => p.Check(bad), bad.ToString());
                Assert.That(e.ParamName, Is.EqualTo("p"));
                StringAssert.StartsWith("p must lie in (0, 2.5], got " + bad.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ".", e.Message);
            }
            // Without a ceiling, the message of any positive number.
            var open = SettingDescriptor.Positive<Probe>("q", "s", 1, "", e => 1);
            StringAssert.StartsWith("q must be a finite number greater than 0, got 0.", Assert.Throws<ArgumentOutOfRangeException>(() => open.Check(0)).Message);
            Assert.That(open.Check(1e300), Is.EqualTo(1e300));
        }

        [Test]
        public void ANumberSettingIsCheckedInItsClosedRangeAndAnUnboundedOneOnlyForFiniteness()
        {
            var closed = Level(0, 2);
            Assert.That(closed.MinExclusive, Is.False);
            Assert.That(closed.Check(0), Is.EqualTo(0.0));
            Assert.That(closed.Check(2), Is.EqualTo(2.0));
            StringAssert.StartsWith("level must lie in [0, 2], got -1.", Assert.Throws<ArgumentOutOfRangeException>(() => closed.Check(-1)).Message);
            var any = Level(double.NegativeInfinity, double.PositiveInfinity);
            Assert.That(any.Check(-1e300), Is.EqualTo(-1e300));
            StringAssert.StartsWith("level must be a finite number, got NaN.", Assert.Throws<ArgumentOutOfRangeException>(() => any.Check(double.NaN)).Message);
            // A range open on one side still takes only finite values, and keeps its other bound.
            foreach (var half in new[] { Level(-1, double.PositiveInfinity), Level(double.NegativeInfinity, 1) })
            {
                foreach (double inf in new[] { double.PositiveInfinity, double.NegativeInfinity, double.NaN })
                    StringAssert.StartsWith("level must be a finite number, got " + inf.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ".",
                        Assert.Throws<ArgumentOutOfRangeException>(() => half.Check(inf)).Message);
                Assert.That(half.Check(0), Is.EqualTo(0.0));
            }
            Assert.That(Level(-1, double.PositiveInfinity).Check(1e300), Is.EqualTo(1e300));
            Assert.That(Level(double.NegativeInfinity, 1).Check(-1e300), Is.EqualTo(-1e300));
            StringAssert.StartsWith("level must lie in [-1, Infinity], got -2.", Assert.Throws<ArgumentOutOfRangeException>(() => Level(-1, double.PositiveInfinity).Check(-2)).Message);
            StringAssert.StartsWith("level must lie in [-Infinity, 1], got 2.", Assert.Throws<ArgumentOutOfRangeException>(() => Level(double.NegativeInfinity, 1).Check(2)).Message);
        }

        [Test]
        public void ABooleanSettingIsOneOrZeroAndWrittenAsTrueOrFalse()
        {
            var b = SettingDescriptor.Boolean<Probe>("on", true, "", e => e.On);
            Assert.That(b.Kind, Is.EqualTo(SettingKind.Boolean));
            Assert.That(b.MinExclusive, Is.False, "off (0) is a value");
            Assert.That(b.Min, Is.EqualTo(0.0));
            Assert.That(b.Max, Is.EqualTo(1.0));
            Assert.That(b.Default, Is.EqualTo(1.0));
            Assert.That(SettingDescriptor.Boolean<Probe>("off", false, "", e => e.On).Default, Is.EqualTo(0.0));
            Assert.That(b.Check(1), Is.EqualTo(1.0));
            Assert.That(b.Check(0), Is.EqualTo(0.0));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => b.Check(0.5));
            Assert.That(e.ParamName, Is.EqualTo("on"));
            StringAssert.StartsWith("on must be true or false (1 or 0), got 0.5.", e.Message);
            Assert.That(b.Format(1), Is.EqualTo("true"));
            Assert.That(b.Format(0), Is.EqualTo("false"));
            Assert.That(b.Format(-2), Is.EqualTo("true"), "any non-zero is on");
            Assert.That(b.Read(new Probe(on: false)), Is.EqualTo(0.0));
            Assert.That(b.Read(new Probe(on: true)), Is.EqualTo(1.0));
            Assert.That(Level(0, 2).Format(0.1), Is.EqualTo("0.1"));
            Assert.That(Level(0, 2).Format(1.0 / 3), Is.EqualTo("0.3333333333333333"));
        }

        [Test]
        public void ASettingNeedsANameAReaderAndAValidDefault()
        {
            foreach (string name in new[] { null, "", "  " })
                StringAssert.StartsWith("a setting needs a name.", Assert.Throws<ArgumentException>(() => SettingDescriptor.Number<Probe>(name, "m", 1, 0, 2, "", e => 1)).Message);
            Assert.That(Assert.Throws<ArgumentNullException>(() => SettingDescriptor.Number<Probe>("n", "m", 1, 0, 2, "", null)).ParamName, Is.EqualTo("read"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => SettingDescriptor.Positive<Probe>("n", "m", 1, "", null)).ParamName, Is.EqualTo("read"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => SettingDescriptor.Boolean<Probe>("n", true, "", null)).ParamName, Is.EqualTo("read"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => Level(0, 2, @default: 3)).ParamName, Is.EqualTo("level"));
            var s = SettingDescriptor.Number<Probe>("n", null, 1, 0, 2, null, e => 1);
            Assert.That(s.Unit, Is.EqualTo(""));
            Assert.That(s.Summary, Is.EqualTo(""));
            Assert.That(s.ToString(), Is.EqualTo("n"));
            Assert.That(s.Min, Is.EqualTo(0.0));
            Assert.That(s.Max, Is.EqualTo(2.0));
        }

        // ---- effects --------------------------------------------------------------------------------------------------

        static EffectDescriptor Declare(string name = "p", Type type = null, Func<EffectSettings, WeightEffect> create = null, params SettingDescriptor[] settings)
            => new EffectDescriptor(name, EffectStage.ObjectMotion, type ?? typeof(Probe), "src", "sum", create ?? (s => new Probe()), settings);

        [Test]
        public void AnEffectNeedsANameAnEffectTypeAFactoryAndDistinctSettings()
        {
            foreach (string name in new[] { null, "", " " })
                StringAssert.StartsWith("an effect needs a name.", Assert.Throws<ArgumentException>(() => Declare(name)).Message);
            foreach (var type in new[] { typeof(string), typeof(WeightEffect).Assembly.GetType("Kosmos.PseudoHaptic.HandPose") })
            {
                var e = Assert.Throws<ArgumentException>(() => Declare("p", type));
                Assert.That(e.ParamName, Is.EqualTo("effectType"));
                StringAssert.StartsWith("effect 'p': effectType must be a WeightEffect.", e.Message);
            }
            Assert.That(Assert.Throws<ArgumentException>(() => new EffectDescriptor("p", EffectStage.Base, null, "", "", s => null)).ParamName, Is.EqualTo("effectType"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => new EffectDescriptor("p", EffectStage.Base, typeof(Probe), "", "", null)).ParamName, Is.EqualTo("create"));
            StringAssert.StartsWith("effect 'p': a setting is null.",
                Assert.Throws<ArgumentException>(() => Declare("p", null, null, Level(0, 2), null)).Message);
            var twice = Assert.Throws<ArgumentException>(() => Declare("p", null, null, Level(0, 2), SettingDescriptor.Boolean<Probe>("on", true, "", e => e.On), Level(0, 3)));
            Assert.That(twice.ParamName, Is.EqualTo("settings"));
            StringAssert.StartsWith("effect 'p' declares setting 'level' twice.", twice.Message);
            // Nothing at all is allowed: no settings, no source or summary.
            var bare = new EffectDescriptor("bare", EffectStage.Base, typeof(Probe), null, null, s => new Probe(), null);
            Assert.That(bare.Settings, Is.Empty);
            Assert.That(bare.Source, Is.EqualTo(""));
            Assert.That(bare.Summary, Is.EqualTo(""));
            StringAssert.StartsWith("effect 'bare' has no setting 'x'; its settings: none.", Assert.Throws<ArgumentException>(() => bare.DefaultSettings().Set("x", 1)).Message);
            Assert.That(bare.ToString(), Is.EqualTo("bare"));
        }

        [Test]
        public void TheDeclaredSettingsAreACopy()
        {
            var settings = new[] { Level(0, 2) };
            var d = Declare("p", null, null, settings);
            settings[0] = Level(0, 5);
            Assert.That(d.Settings[0].Max, Is.EqualTo(2.0));
        }

        [Test]
        public void CreateChecksEverySettingAndWhatTheFactoryBuilt()
        {
            var d = Probe.Descriptor;
            Assert.Throws<ArgumentNullException>(() => d.Create(null));
            var foreign = Assert.Throws<ArgumentException>(() => d.Create(FloorClamp.Descriptor.DefaultSettings()));
            StringAssert.StartsWith("settings of 'floor-clamp' given to 'descriptor-probe'.", foreign.Message);
            var s = d.DefaultSettings();
            s[0] = 3;
            var bad = Assert.Throws<EffectSettingException>(() => d.Create(s));
            Assert.That(bad.Message, Is.EqualTo("effect 'descriptor-probe': setting 'level': level must lie in [0, 2], got 3."));
            Assert.That(bad.ParamName, Is.EqualTo("level"));
            Assert.That(bad.InnerException, Is.InstanceOf<ArgumentOutOfRangeException>());
            s[0] = 1.5;
            s[1] = 0;
            var built = (Probe)d.Create(s);
            Assert.That(built.Level, Is.EqualTo(1.5));
            Assert.That(built.On, Is.False);

            string Built(Func<EffectSettings, WeightEffect> create, string name = "descriptor-probe", EffectStage stage = EffectStage.ObjectMotion)
            {
                var x = new EffectDescriptor(name, stage, typeof(Probe), "", "", create);
                return Assert.Throws<InvalidOperationException>(() => x.Create(x.DefaultSettings())).Message;
            }
            Assert.That(Built(_ => null), Is.EqualTo("effect 'descriptor-probe': its factory built nothing."));
            Assert.That(Built(_ => new FloorClamp()), Is.EqualTo("effect 'descriptor-probe': its factory built FloorClamp 'floor-clamp' of stage Position."));
            Assert.That(Built(_ => new Probe(), name: "other"), Is.EqualTo("effect 'other': its factory built Probe 'descriptor-probe' of stage ObjectMotion."));
            Assert.That(Built(_ => new Probe(), stage: EffectStage.Gain), Is.EqualTo("effect 'descriptor-probe': its factory built Probe 'descriptor-probe' of stage ObjectMotion."));
        }

        [Test]
        public void AFactorysOwnRefusalIsPassedOnNamingTheEffectAndTheSettingItNames()
        {
            var named = new EffectDescriptor("descriptor-probe", EffectStage.ObjectMotion, typeof(Probe), "", "",
                _ => throw new ArgumentOutOfRangeException("level", 9.0, "level and on disagree"));
            var e = Assert.Throws<EffectSettingException>(() => named.Create(named.DefaultSettings()));
            Assert.That(e.Message, Is.EqualTo("effect 'descriptor-probe': setting 'level': level and on disagree"), "without .NET's appended lines");
            Assert.That(e.ParamName, Is.EqualTo("level"));
            var unnamed = new EffectDescriptor("descriptor-probe", EffectStage.ObjectMotion, typeof(Probe), "", "",
                _ => throw new ArgumentException("no good"));
            var u = Assert.Throws<EffectSettingException>(() => unnamed.Create(unnamed.DefaultSettings()));
            Assert.That(u.Message, Is.EqualTo("effect 'descriptor-probe': no good"));
            Assert.That(u.ParamName, Is.Null);
            // Another kind of exception is not a setting's fault: it passes through as it is.
            var other = new EffectDescriptor("descriptor-probe", EffectStage.ObjectMotion, typeof(Probe), "", "", _ => throw new InvalidOperationException("x"));
            Assert.That(Assert.Throws<InvalidOperationException>(() => other.Create(other.DefaultSettings())).Message, Is.EqualTo("x"));
        }

        [TestCase("plain", "plain")]
        [TestCase("a bad value (Parameter 'level')", "a bad value")]
        [TestCase("first line\nsecond", "first line")]
        [TestCase("first line\r\nsecond", "first line")]
        [TestCase("\nsecond", "")]
        [TestCase("a value (Parameter 'x')\r\nActual value was 3.", "a value")]
        [TestCase(" (Parameter 'x') at the start", "")]
        [TestCase("mentions (Parameter without its quote", "mentions (Parameter without its quote")]
        public void OnlyTheMessagesFirstLineIsKept(string message, string kept)
        {
            var d = new EffectDescriptor("descriptor-probe", EffectStage.ObjectMotion, typeof(Probe), "", "", _ => throw new ArgumentException(message));
            Assert.That(Assert.Throws<EffectSettingException>(() => d.Create(d.DefaultSettings())).Message, Is.EqualTo("effect 'descriptor-probe': " + kept));
        }

        [Test]
        public void TheSettingsOfAnEffectAreReadFromItAndOnlyFromItsOwnType()
        {
            var s = Probe.Descriptor.SettingsOf(new Probe(1.25, false));
            Assert.That(s[0], Is.EqualTo(1.25));
            Assert.That(s[1], Is.EqualTo(0.0));
            Assert.That(s.Effect, Is.SameAs(Probe.Descriptor));
            foreach (WeightEffect wrong in new WeightEffect[] { null, new FloorClamp() })
            {
                var e = Assert.Throws<ArgumentException>(() => Probe.Descriptor.SettingsOf(wrong));
                Assert.That(e.ParamName, Is.EqualTo("effect"));
                StringAssert.StartsWith("not a 'descriptor-probe' effect.", e.Message);
            }
        }

        // ---- settings values ------------------------------------------------------------------------------------------

        [Test]
        public void SettingsStartAtTheDefaultsAndAreSetByNameOrIndex()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => new EffectSettings(null)).ParamName, Is.EqualTo("effect"));
            var s = Probe.Descriptor.DefaultSettings();
            Assert.That(s.Count, Is.EqualTo(2));
            Assert.That(s[0], Is.EqualTo(0.5));
            Assert.That(s.Flag(1), Is.True);
            Assert.That(s.IndexOf("on"), Is.EqualTo(1));
            Assert.That(s.IndexOf("level"), Is.EqualTo(0));
            Assert.That(s.IndexOf("Level"), Is.EqualTo(-1), "names are case-sensitive, as the file's keys");
            Assert.That(s.Set("level", 2).Set("on", 0), Is.SameAs(s));
            Assert.That(s.Flag(1), Is.False);
            s[1] = 0.25;
            Assert.That(s.Flag(1), Is.True, "any non-zero is on");
            Assert.That(s.Pairs().Select(p => p.Key + "=" + p.Value), Is.EqualTo(new[] { "level=2", "on=0.25" }));
            var e = Assert.Throws<ArgumentException>(() => s.Set("lvl", 1));
            Assert.That(e.ParamName, Is.EqualTo("name"));
            StringAssert.StartsWith("effect 'descriptor-probe' has no setting 'lvl'; its settings: level, on.", e.Message);
            s[1] = 1;
            Assert.That(((Probe)s.Build()).Level, Is.EqualTo(2.0));
        }

        // ---- the registry ---------------------------------------------------------------------------------------------

        [Test]
        public void TheRegistryListsThePackageFirstAndRefusesWhatItCannotHold()
        {
            EffectRegistry.Register(Probe.Descriptor);
            EffectRegistry.Register(Probe.Descriptor); // again: nothing
            Assert.That(EffectRegistry.All.Take(EffectRegistry.Package.Count), Is.EqualTo(EffectRegistry.Package));
            Assert.That(EffectRegistry.All.Count(d => d == Probe.Descriptor), Is.EqualTo(1));
            Assert.That(EffectRegistry.Find("descriptor-probe"), Is.SameAs(Probe.Descriptor));
            Assert.That(EffectRegistry.Find(typeof(Probe)), Is.SameAs(Probe.Descriptor));
            Assert.That(EffectRegistry.Of(new Probe()), Is.SameAs(Probe.Descriptor));
            Assert.That(EffectRegistry.Find("unregistered"), Is.Null);
            Assert.That(EffectRegistry.Find(typeof(Unregistered)), Is.Null);

            Assert.That(Assert.Throws<ArgumentNullException>(() => EffectRegistry.Register(null)).ParamName, Is.EqualTo("effect"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => EffectRegistry.Of(null)).ParamName, Is.EqualTo("effect"));
            var of = Assert.Throws<ArgumentException>(() => EffectRegistry.Of(new Unregistered()));
            StringAssert.StartsWith("effect 'unregistered' (" + typeof(Unregistered).FullName + ") is not registered: EffectRegistry.Register its descriptor.", of.Message);
            var sameType = new EffectDescriptor("probe-again", EffectStage.ObjectMotion, typeof(Probe), "", "", _ => new Probe());
            var clash = Assert.Throws<ArgumentException>(() => EffectRegistry.Register(sameType));
            StringAssert.StartsWith("effect 'probe-again' (Probe): 'descriptor-probe' (Probe) is registered with that name or type.", clash.Message);
            var sameName = new EffectDescriptor("descriptor-probe", EffectStage.Position, typeof(Unregistered), "", "", _ => new Unregistered());
            StringAssert.StartsWith("effect 'descriptor-probe' (Unregistered): 'descriptor-probe' (Probe) is registered",
                Assert.Throws<ArgumentException>(() => EffectRegistry.Register(sameName)).Message);
            var unknown = Assert.Throws<ArgumentException>(() => EffectRegistry.Get("heavy"));
            Assert.That(unknown.ParamName, Is.EqualTo("name"));
            StringAssert.StartsWith("effect 'heavy' is unknown; known effects: " + string.Join(", ", EffectRegistry.All.Select(d => d.Name)) + ".", unknown.Message);
            Assert.That(EffectRegistry.Get("speed-cap"), Is.SameAs(SpeedCap.Descriptor));
        }
    }
}
