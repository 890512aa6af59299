using System;
using System.Reflection;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The discrimination task's inspector fields and <see cref="DiscriminationSettings"/> (<see cref="DiscriminationTask.Use"/>
    /// and <see cref="DiscriminationTask.Settings"/>): every setting, found by reflection so that one added later is
    /// checked too, goes in and comes back out.
    /// </summary>
    public sealed class DiscriminationTaskSettingsTests : PlayModeFixture
    {
        static readonly FieldInfo[] SettingFields = typeof(DiscriminationSettings).GetFields(BindingFlags.Public | BindingFlags.Instance);

        /// <summary>Settings whose every field differs from the inspector's default (values a float holds exactly).</summary>
        static DiscriminationSettings Distinct()
        {
            var s = new DiscriminationSettings();
            for (int i = 0; i < SettingFields.Length; i++)
            {
                FieldInfo f = SettingFields[i];
                if (f.FieldType == typeof(double)) f.SetValue(s, 0.25 * (i + 3));
                else if (f.FieldType == typeof(int)) f.SetValue(s, 1000 + i);
                else if (f.FieldType == typeof(double[])) f.SetValue(s, new[] { 0.125 * (i + 1), 0.75, 1.5 });
                else if (f.FieldType == typeof(DiscriminationProcedure)) f.SetValue(s, DiscriminationProcedure.Staircase1Up3Down);
                else Assert.Fail("no test value for " + f.Name + " (" + f.FieldType.Name + "): add one here");
            }
            return s;
        }

        static void AssertSame(DiscriminationSettings expected, DiscriminationSettings actual, string what)
        {
            foreach (FieldInfo f in SettingFields)
                Assert.That(f.GetValue(actual), Is.EqualTo(f.GetValue(expected)), what + ": " + f.Name);
        }

        DiscriminationTask Task() => Track(new GameObject("Task")).AddComponent<DiscriminationTask>();

        [Test]
        public void EverySettingTakenByUseComesBackFromSettings()
        {
            Assert.That(SettingFields.Length, Is.GreaterThanOrEqualTo(14), "reflection found the settings");
            DiscriminationTask task = Task();
            DiscriminationSettings given = Distinct();
            DiscriminationSettings before = task.Settings;
            foreach (FieldInfo f in SettingFields)
                Assert.That(f.GetValue(before), Is.Not.EqualTo(f.GetValue(given)), "the test value of " + f.Name + " is the default: it would not show a missing copy");

            task.Use(given);
            AssertSame(given, task.Settings, "in by Use, out by Settings");
            AssertSame(Distinct(), given, "Use changed the settings it was given");
        }

        [Test]
        public void UseKeepsNoArrayOfTheSettingsAndSettingsGivesNoneOfTheTask()
        {
            DiscriminationTask task = Task();
            DiscriminationSettings given = Distinct();
            task.Use(given);
            given.ComparisonKg[0] = 99;
            given.CatchKg[0] = 99;
            Assert.That(task.Settings.ComparisonKg[0], Is.Not.EqualTo(99), "the task shares the comparison array it was given");
            Assert.That(task.Settings.CatchKg[0], Is.Not.EqualTo(99), "the task shares the catch array it was given");

            DiscriminationSettings read = task.Settings;
            read.ComparisonKg[0] = 42;
            Assert.That(task.Settings.ComparisonKg[0], Is.Not.EqualTo(42), "Settings hands out the task's own array");
        }

        [Test]
        public void TheInspectorDefaultsSurviveARoundTrip()
        {
            DiscriminationTask task = Task();
            DiscriminationSettings defaults = task.Settings;
            task.Use(defaults);
            AssertSame(defaults, task.Settings, "Use(Settings)");
            Assert.That(task.Plan().Levels, Is.EqualTo(defaults.ComparisonKg), "the plan is the settings' plan");
        }

        [Test]
        public void NoSettingsAreRefusedNamingThem()
        {
            DiscriminationTask task = Task();
            Assert.That(() => task.Use(null), Throws.TypeOf<ArgumentNullException>().With.Property("ParamName").EqualTo("settings"));
        }
    }
}
