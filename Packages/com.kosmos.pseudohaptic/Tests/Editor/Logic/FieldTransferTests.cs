using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// One list of fields, run both ways (<see cref="FieldTransfer"/>): each direction copies only its way, floats and
    /// doubles meet at the nearest float, arrays are copied and never shared, and a field read into settings and
    /// written back is what it was.
    /// </summary>
    public sealed class FieldTransferTests
    {
        [Test]
        public void EachDirectionWritesOnlyItsOwnSide()
        {
            int setting = 1, field = 2;
            FieldTransfer.Copy(TransferDirection.FieldsToSettings, ref setting, ref field);
            Assert.That(setting, Is.EqualTo(2));
            Assert.That(field, Is.EqualTo(2), "the field is left as it was");
            setting = 3;
            FieldTransfer.Copy(TransferDirection.SettingsToFields, ref setting, ref field);
            Assert.That(field, Is.EqualTo(3));
            Assert.That(setting, Is.EqualTo(3), "the setting is left as it was");

            var procedure = DiscriminationProcedure.Staircase1Up3Down;
            var inspector = DiscriminationProcedure.ConstantStimuli;
            FieldTransfer.Copy(TransferDirection.SettingsToFields, ref procedure, ref inspector);
            Assert.That(inspector, Is.EqualTo(DiscriminationProcedure.Staircase1Up3Down));
            inspector = DiscriminationProcedure.Staircase1Up2Down;
            FieldTransfer.Copy(TransferDirection.FieldsToSettings, ref procedure, ref inspector);
            Assert.That(procedure, Is.EqualTo(DiscriminationProcedure.Staircase1Up2Down));
        }

        [Test]
        public void ADoubleMeetsItsFloatFieldAtTheNearestFloat()
        {
            double setting = 0.1;
            float field = 0;
            FieldTransfer.Copy(TransferDirection.SettingsToFields, ref setting, ref field);
            Assert.That(field, Is.EqualTo(0.1f));
            Assert.That(setting, Is.EqualTo(0.1), "the setting is left as it was");
            FieldTransfer.Copy(TransferDirection.FieldsToSettings, ref setting, ref field);
            Assert.That(setting, Is.EqualTo((double)0.1f), "widened exactly, not rounded back to 0.1");
        }

        [Test]
        public void ArraysAreCopiedNeverSharedAndNullIsEmpty()
        {
            double[] setting = { 0.35, 2 };
            float[] field = null;
            FieldTransfer.Copy(TransferDirection.SettingsToFields, ref setting, ref field);
            Assert.That(field, Is.EqualTo(new[] { 0.35f, 2f }));
            setting[0] = 9;
            Assert.That(field[0], Is.EqualTo(0.35f), "the field shares the settings' array");

            FieldTransfer.Copy(TransferDirection.FieldsToSettings, ref setting, ref field);
            Assert.That(setting, Is.EqualTo(new[] { (double)0.35f, 2.0 }));
            field[1] = 7;
            Assert.That(setting[1], Is.EqualTo(2.0), "the settings share the field's array");

            setting = null;
            FieldTransfer.Copy(TransferDirection.SettingsToFields, ref setting, ref field);
            Assert.That(field, Is.Not.Null.And.Empty);
            field = null;
            FieldTransfer.Copy(TransferDirection.FieldsToSettings, ref setting, ref field);
            Assert.That(setting, Is.Not.Null.And.Empty);
        }

        [Test]
        public void FieldsReadIntoSettingsAndWrittenBackAreWhatTheyWere()
        {
            // Any float field (here odd ones) survives the round trip exactly, so a component's Use(Settings) changes nothing.
            float[] values = { 0.1f, 1e-7f, 3.4e38f, -0.0f, 0.7f * 0.3f };
            foreach (float v in values)
            {
                double setting = double.NaN;
                float field = v;
                FieldTransfer.Copy(TransferDirection.FieldsToSettings, ref setting, ref field);
                field = float.NaN;
                FieldTransfer.Copy(TransferDirection.SettingsToFields, ref setting, ref field);
                Assert.That(field, Is.EqualTo(v), v.ToString("R"));
            }
            float[] array = values;
            double[] read = null;
            FieldTransfer.Copy(TransferDirection.FieldsToSettings, ref read, ref array);
            array = null;
            FieldTransfer.Copy(TransferDirection.SettingsToFields, ref read, ref array);
            Assert.That(array, Is.EqualTo(values));
        }
    }
}
