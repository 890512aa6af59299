using System;
using System.Linq;
using System.Reflection;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Issue 33 item 1: each effect declares its settings once (<see cref="EffectDescriptor"/>), and what it declares is
    /// what the effect enforces and holds.</summary>
    public class EffectDescriptorTests
    {
        static EffectDescriptor[] Package => EffectRegistry.Package.ToArray();

        [Test]
        public void EveryEffectOfThePackageIsRegisteredOnceAndEveryNamedProfileUsesOnlyThose()
        {
            Assert.That(Package.Select(d => d.Name).Distinct().Count(), Is.EqualTo(Package.Length));
            Assert.That(Package.Select(d => d.EffectType).Distinct().Count(), Is.EqualTo(Package.Length));
            foreach (string name in NamedProfiles.Names)
                foreach (var e in NamedProfiles.Get(name).Effects)
                    Assert.That(EffectRegistry.Of(e), Is.SameAs(EffectRegistry.Find(e.Name)), name + ": " + e.Name);
            // Every WeightEffect class of the core is registered (a new effect without a descriptor fails here).
            var classes = typeof(WeightEffect).Assembly.GetTypes().Where(t => t.IsSubclassOf(typeof(WeightEffect)) && !t.IsAbstract).ToArray();
            Assert.That(classes.Where(t => EffectRegistry.Find(t) == null), Is.Empty);
        }

        [Test]
        public void EachDescriptorsNameStageAndDefaultsAreTheEffects()
        {
            foreach (var d in Package)
            {
                var built = d.Create(d.DefaultSettings());
                Assert.That(built.Name, Is.EqualTo(d.Name));
                Assert.That(built.Stage, Is.EqualTo(d.Stage));
                Assert.That(d.Summary, Is.Not.Empty, d.Name);
                var readBack = d.SettingsOf(built);
                for (int i = 0; i < d.Settings.Count; i++)
                    Assert.That(readBack[i], Is.EqualTo(d.Settings[i].Default), d.Name + "." + d.Settings[i].Name);
                // The C# constructor's optional parameters give the same effect as the declared defaults (BreakAway has no
                // default in C#: a distance must be given).
                var ctor = d.EffectType.GetConstructors().Single();
                if (ctor.GetParameters().All(p => p.IsOptional))
                {
                    var byCtor = (WeightEffect)ctor.Invoke(ctor.GetParameters().Select(_ => Type.Missing).ToArray());
                    var s = d.SettingsOf(byCtor);
                    for (int i = 0; i < d.Settings.Count; i++)
                        Assert.That(s[i], Is.EqualTo(d.Settings[i].Default), d.Name + "." + d.Settings[i].Name + ": the constructor's default");
                }
                // The settings are the constructor's parameters, by name and order.
                Assert.That(ctor.GetParameters().Select(p => p.Name), Is.EqualTo(d.Settings.Select(x => x.Name)), d.Name);
            }
        }

        [Test]
        public void EveryEffectSaysWhereItComesFromAndEverySettingWhatItIsInAUnitTheDocsWrite()
        {
            // The tool's listing, ALGORITHM.md's generated effects table and the Unity list show the source and the summaries:
            // none may be blank. A unit is SI as the docs write it ("" for a ratio), or a multiple of a named speed.
            var units = new[] { "", "m", "s", "m/s", "kg" };
            foreach (var d in Package)
            {
                Assert.That(string.IsNullOrWhiteSpace(d.Source), Is.False, d.Name + ": where it comes from");
                Assert.That(string.IsNullOrWhiteSpace(d.Summary), Is.False, d.Name + ": what it does");
                foreach (var s in d.Settings)
                {
                    Assert.That(string.IsNullOrWhiteSpace(s.Summary), Is.False, d.Name + "." + s.Name + ": what it is");
                    Assert.That(Array.IndexOf(units, s.Unit) >= 0 || System.Text.RegularExpressions.Regex.IsMatch(s.Unit, "^× v_[a-z]+$"), Is.True,
                        d.Name + "." + s.Name + ": unit '" + s.Unit + "'");
                }
            }
            // The profile's limits too (the same listing, table and file format show them).
            foreach (var s in SolverLimits.Settings)
                Assert.That(string.IsNullOrWhiteSpace(s.Summary), Is.False, "limits." + s.Name + ": what it is");
        }

        [Test]
        public void TheDeclaredRangeIsTheRangeTheEffectEnforcesAndTheMessageNamesEffectAndSetting()
        {
            int checkedEnds = 0;
            foreach (var d in Package)
                for (int i = 0; i < d.Settings.Count; i++)
                {
                    var setting = d.Settings[i];
                    if (setting.Kind != SettingKind.Number) continue;
                    foreach (double end in new[] { setting.Min, setting.Max })
                    {
                        if (double.IsInfinity(end)) continue;
                        bool isMin = end == setting.Min;
                        double outside = isMin ? end - Math.Max(1e-9, Math.Abs(end) * 1e-6) : end + Math.Max(1e-9, Math.Abs(end) * 1e-6);
                        var s = d.DefaultSettings();
                        s[i] = end;
                        if (!(isMin && setting.MinExclusive))
                            Assert.DoesNotThrow(() => d.Create(s), d.Name + "." + setting.Name + " = " + end);
                        s[i] = outside;
                        var e = Assert.Catch<ArgumentException>(() => d.Create(s), d.Name + "." + setting.Name + " = " + outside);
                        Assert.That(e.Message, Does.StartWith("effect '" + d.Name + "': setting '" + setting.Name + "':"));
                        // The constructor enforces the same range on its own (the declared range is the enforced one).
                        var args = d.DefaultSettings();
                        args[i] = outside;
                        var direct = Assert.Throws<TargetInvocationException>(() => d.EffectType.GetConstructors().Single().Invoke(Enumerable.Range(0, args.Count).Select(k => d.Settings[k].Kind == SettingKind.Boolean ? (object)(args[k] != 0) : args[k]).ToArray()));
                        Assert.That(direct.InnerException, Is.InstanceOf<ArgumentOutOfRangeException>());
                        Assert.That(((ArgumentException)direct.InnerException).ParamName, Is.EqualTo(setting.Name));
                        checkedEnds++;
                    }
                    var nan = d.DefaultSettings();
                    nan[i] = double.NaN;
                    Assert.Catch<ArgumentException>(() => d.Create(nan), d.Name + "." + setting.Name + " = NaN");
                }
            Assert.That(checkedEnds, Is.GreaterThan(30));
        }

        [Test]
        public void ABooleanSettingTakesOnlyOnOrOff()
        {
            var s = TrackingLossHold.Descriptor.DefaultSettings();
            s[1] = 0.5;
            var e = Assert.Catch<ArgumentException>(() => s.Build());
            Assert.That(e.Message, Does.Contain("tracking-loss-hold").And.Contain("requireHighConfidence"));
            s[1] = 0;
            Assert.That(((TrackingLossHold)s.Build()).RequireHighConfidence, Is.False);
        }

        [Test]
        public void AnUnknownSettingOrEffectNamesItAndTheChoices()
        {
            var e = Assert.Catch<ArgumentException>(() => OffsetCorrection.Descriptor.DefaultSettings().Set("treshold", 0.1));
            Assert.That(e.Message, Does.Contain("offset-correction").And.Contain("treshold").And.Contain("threshold, band"));
            var u = Assert.Catch<ArgumentException>(() => EffectRegistry.Get("heavyness"));
            Assert.That(u.Message, Does.Contain("heavyness").And.Contain("speed-cap"));
        }

        [Test]
        public void ARegisteredNameOrTypeCannotBeTakenByAnotherDescriptor()
        {
            var clash = new EffectDescriptor("speed-cap", EffectStage.Position, typeof(ScaledOffset), "", "", s => new ScaledOffset(1));
            Assert.Catch<ArgumentException>(() => EffectRegistry.Register(clash));
            Assert.DoesNotThrow(() => EffectRegistry.Register(SpeedCap.Descriptor)); // the same descriptor again: nothing
        }

        [Test]
        public void TheLimitsDeclareTheirSettingsAsTheyEnforceThem()
        {
            for (int i = 0; i < SolverLimits.Settings.Count; i++)
                Assert.That(SolverLimits.Settings[i].Read(SolverLimits.Default), Is.EqualTo(SolverLimits.Settings[i].Default), SolverLimits.Settings[i].Name);
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new SolverLimits(maxGain: 0.5));
            Assert.That(e.ParamName, Is.EqualTo("maxGain"));
        }
    }
}
