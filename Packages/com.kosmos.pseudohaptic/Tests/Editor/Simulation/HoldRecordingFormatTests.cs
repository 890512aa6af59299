using System;
using System.IO;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The recording format's documented edges: the capacity's floor, null arguments, no hand when untracked or
    /// garbage, profile names cleaned wherever the unsafe character is, columns by name in any order, empty optional
    /// fields as NaN, flags 1/0/true/false, a BOM and quotes tolerated, and errors naming the file (or
    /// &lt;recording&gt;), the line, the column and the bad value.
    /// </summary>
    public class HoldRecordingFormatTests
    {
        static WeightSolver Solver() => new WeightSolver(WeightModel.FromMass(1.0), NamedProfiles.Get(NamedProfiles.PaperName), 0.5);

        static HoldRecording Read(string text, string source = "hold.csv") => HoldRecording.ReadCsv(new StringReader(text), source);

        static string ErrorOf(string text, string source = "hold.csv")
            => Assert.Throws<FormatException>(() => Read(text, source)).Message;

        [Test]
        public void ACapacityOfOneFrameIsEnoughAndLessIsRefused()
        {
            Assert.That(new HoldRecording(1).Capacity, Is.EqualTo(1));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new HoldRecording(0));
            Assert.That(e.ParamName, Is.EqualTo("capacity"));
            Assert.That(e.Message, Does.Contain("at least 1"));
        }

        [Test]
        public void NullArgumentsAreRefused()
        {
            var r = new HoldRecording();
            var hand = new HandSample(1.0);
            Assert.Throws<ArgumentNullException>(() => r.Begin(null, in hand));
            Assert.Throws<ArgumentNullException>(() => r.Step(null, in hand, 0.01));
            Assert.Throws<ArgumentNullException>(() => r.WriteCsv(null));
            Assert.Throws<ArgumentNullException>(() => HoldRecording.ReadCsv(null, "hold.csv"));
        }

        [Test]
        public void AnUntrackedOrGarbageHandIsRecordedAsNoHand()
        {
            var solver = Solver();
            solver.BeginHold(1.0, 1.0);
            var r = new HoldRecording();
            var begin = new HandSample(1.0, true, true, 0);
            r.Begin(solver, in begin);
            var untracked = new HandSample(0.9, false, false, 0.01);
            var infinite = new HandSample(double.PositiveInfinity, true, true, 0.02);
            var fine = new HandSample(0.95, true, false, 0.03);
            r.Step(solver, in untracked, 0.01);
            r.Step(solver, in infinite, 0.01);
            r.Step(solver, in fine, 0.01);
            Assert.That(r[0].HandY, Is.EqualTo(1.0));
            Assert.That(r[1].HandY, Is.NaN);
            Assert.That(r[1].Tracked, Is.False);
            Assert.That(r[2].HandY, Is.NaN);
            Assert.That(r[2].Tracked, Is.True);
            Assert.That(r[3].HandY, Is.EqualTo(0.95));
            Assert.That(r[3].HighConfidence, Is.False);
        }

        [Test]
        public void AProfileNameIsCleanedEvenWhenItStartsWithAnUnsafeCharacterAndANullNameIsEmpty()
        {
            var r = new HoldRecording();
            r.Add(new RecordedFrame { Time = 0, HandY = 1, Tracked = true, HighConfidence = true, Profile = ",lead" });
            r.Add(new RecordedFrame { Time = 0.1, HandY = 1, Tracked = true, HighConfidence = true, Profile = null });
            string csv = r.ToCsv();
            Assert.That(csv, Does.Contain(",_lead,"));
            var back = Read(csv);
            Assert.That(back.Count, Is.EqualTo(2));
            Assert.That(back[0].Profile, Is.EqualTo("_lead"));
            Assert.That(back[1].Profile, Is.EqualTo(""));
        }

        [Test]
        public void AByteOrderMarkBeforeTheHeaderIsIgnoredAndAnEmptyHeaderIsAnError()
        {
            var r = Read("\uFEFFt,hand_y\n0,1\n");
            Assert.That(r.Count, Is.EqualTo(1));
            Assert.That(r[0].HandY, Is.EqualTo(1.0));
            Assert.That(ErrorOf("\n0,1\n"), Is.EqualTo("hold.csv:1: missing column 't'"));
        }

        [Test]
        public void UnnamedColumnsAreIgnored()
        {
            var r = Read("t,hand_y,,\n0,1,,\n");
            Assert.That(r.Count, Is.EqualTo(1));
            Assert.That(r[0].HandY, Is.EqualTo(1.0));
        }

        [Test]
        public void ColumnsAreFoundByNameInAnyOrder()
        {
            var a = Read("hand_y,t\n0.7,0.5\n");
            Assert.That(a[0].HandY, Is.EqualTo(0.7));
            Assert.That(a[0].Time, Is.EqualTo(0.5));
            var b = Read("profile,t,hand_y\nlead,0,1\n");
            Assert.That(b[0].Profile, Is.EqualTo("lead"));
            var c = Read("tracked,t,hand_y\n0,0,\n");
            Assert.That(c[0].Tracked, Is.False);
            Assert.That(c[0].HighConfidence, Is.False);
        }

        [Test]
        public void EmptyOptionalFieldsReadAsNaNAndConfidenceFollowsTracked()
        {
            var r = Read(HoldRecording.Header + "\n0,1,1,,,,,,\n");
            Assert.That(r[0].PoseTime, Is.NaN);
            Assert.That(r[0].ObjectY, Is.NaN);
            Assert.That(r[0].MassKg, Is.NaN);
            Assert.That(r[0].StandardSpeed, Is.NaN);
            Assert.That(r[0].HighConfidence, Is.True);
        }

        [TestCase("1", true)]
        [TestCase("0", false)]
        [TestCase("true", true)]
        [TestCase("FALSE", false)]
        public void FlagsReadAsOneZeroTrueOrFalse(string flag, bool expected)
        {
            var r = Read("t,hand_y,tracked,high_confidence\n0,1," + flag + "," + flag + "\n");
            Assert.That(r[0].Tracked, Is.EqualTo(expected));
            Assert.That(r[0].HighConfidence, Is.EqualTo(expected));
        }

        [Test]
        public void QuotedFieldsReadAsTheirContent()
        {
            var r = Read("\"t\",\"hand_y\",\"profile\"\n\"0.5\",\"1\",\"\"\n");
            Assert.That(r[0].Time, Is.EqualTo(0.5));
            Assert.That(r[0].HandY, Is.EqualTo(1.0));
            Assert.That(r[0].Profile, Is.EqualTo(""));
            Assert.That(Read("t,hand_y,profile\n0,1,\"\n")[0].Profile, Is.EqualTo("\""));
        }

        [TestCase("pose_t")]
        [TestCase("object_y")]
        [TestCase("mass_kg")]
        [TestCase("standard_speed")]
        [TestCase("hand_y")]
        public void ABadNumberNamesTheFileLineColumnAndValue(string column)
        {
            string header = HoldRecording.Header;
            string[] names = header.Split(',');
            var fields = new[] { "0", "1", "1", "0", "1", "1", "paper", "1", "0.5" };
            fields[Array.IndexOf(names, column)] = "abc";
            Assert.That(ErrorOf(header + "\n" + string.Join(",", fields) + "\n"),
                Is.EqualTo("hold.csv:2: column '" + column + "': cannot parse 'abc' as a number"));
        }

        [Test]
        public void ABadFlagNamesTheFileLineColumnAndValue()
        {
            Assert.That(ErrorOf("t,hand_y,high_confidence\n0,1,yes\n"),
                Is.EqualTo("hold.csv:2: column 'high_confidence': expected 1 or 0, found 'yes'"));
        }

        [Test]
        public void ADuplicateColumnIsNamed()
        {
            Assert.That(ErrorOf("t,hand_y,t\n"), Is.EqualTo("hold.csv:1: column 't' appears twice"));
        }

        [TestCase(null)]
        [TestCase("")]
        public void WithoutASourceNameTheErrorSaysRecording(string source)
        {
            Assert.That(ErrorOf("t,hand_y\n0,x\n", source), Does.StartWith("<recording>:2: "));
        }
    }
}
