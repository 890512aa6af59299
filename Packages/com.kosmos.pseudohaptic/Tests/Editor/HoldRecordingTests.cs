using System;
using System.IO;
using System.Text;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Session recording: frames into a preallocated buffer, out as a replay trace, back in unchanged.</summary>
    public class HoldRecordingTests
    {
        const double Dt = 1 / 90.0;

        /// <summary>
        /// A lift recorded as <c>SessionRecorder</c> records it: 90 Hz frames, 30 Hz poses, a short tracking loss
        /// and a low-confidence stretch if asked, the hand starting at the object's height.
        /// </summary>
        static HoldRecording Record(WeightSolver solver, int frames, bool withLosses, HoldRecording recording = null)
        {
            recording = recording ?? new HoldRecording();
            var begin = new HandSample(0.8, true, true, 0);
            solver.BeginHold(begin.Y, begin.Y, begin.PoseTime);
            recording.Begin(solver, in begin);
            for (int i = 1; i < frames; i++)
            {
                double t = i * Dt, poseT = Math.Floor(t * 30) / 30;
                double u = Math.Min(1, poseT / 1.0);
                double y = 0.8 + 0.3 * u * u * u * (10 - 15 * u + 6 * u * u);
                bool lost = withLosses && i >= 40 && i < 46;
                bool unsure = withLosses && i >= 60 && i < 64;
                var sample = lost ? HandSample.Lost : new HandSample(y, true, !unsure, poseT);
                solver.Step(in sample, Dt);
                recording.Step(solver, in sample, Dt);
            }
            return recording;
        }

        static WeightSolver Solver(double massKg = 1.0, string profile = NamedProfiles.PaperName, double speed = 0.5)
            => new WeightSolver(WeightModel.FromMass(massKg), NamedProfiles.Get(profile), speed);

        static bool Same(double a, double b) => a.Equals(b); // NaN equals NaN, bit for bit otherwise

        [Test]
        public void TheHeaderStartsWithTheReplayColumns()
        {
            string header = new HoldRecording().ToCsv().TrimEnd('\n');
            Assert.That(header, Is.EqualTo(HoldRecording.Header));
            Assert.That(header, Does.StartWith("t,hand_y,tracked,pose_t,"));
            Assert.That(header.Split(','), Is.SupersetOf(new[] { "object_y", "mass_kg", "profile" }));
        }

        [Test]
        public void WrittenAndReadBackEveryFrameIsTheSame()
        {
            var recording = Record(Solver(1.3), 180, withLosses: true);
            Assert.That(recording.Count, Is.EqualTo(180));

            string dir = Path.Combine(Path.GetTempPath(), "ph-recording-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string path = Path.Combine(dir, "hold-001-box.csv");
                AtomicFile.WriteWith(path, temp =>
                {
                    using (var writer = new StreamWriter(temp, false, new UTF8Encoding(false))) recording.WriteCsv(writer);
                });
                string[] lines = File.ReadAllText(path).Split('\n');
                Assert.That(lines[0], Is.EqualTo(HoldRecording.Header));
                Assert.That(lines, Has.Length.EqualTo(180 + 2), "header, one row per frame, and the final line end");
                Assert.That(lines[181], Is.Empty);
                Assert.That(lines[1], Does.StartWith("0,0.8,1,0,0.8,1.3,paper,1,0.5"));
                Assert.That(lines[1 + 42], Does.StartWith(lines[1 + 42].Split(',')[0] + ",,0,,"), "a lost frame: no hand, not tracked, no pose time");

                HoldRecording back;
                using (var reader = new StreamReader(path)) back = HoldRecording.ReadCsv(reader, path);
                Assert.That(back.Count, Is.EqualTo(recording.Count));
                for (int i = 0; i < recording.Count; i++)
                {
                    RecordedFrame a = recording[i], b = back[i];
                    Assert.That(Same(a.Time, b.Time) && Same(a.HandY, b.HandY) && Same(a.PoseTime, b.PoseTime) && Same(a.ObjectY, b.ObjectY)
                                && Same(a.MassKg, b.MassKg) && Same(a.StandardSpeed, b.StandardSpeed), Is.True, "frame " + i);
                    Assert.That(b.Tracked, Is.EqualTo(a.Tracked), "frame " + i);
                    Assert.That(b.HighConfidence, Is.EqualTo(a.HighConfidence), "frame " + i);
                    Assert.That(b.Profile, Is.EqualTo("paper"));
                }
                Assert.That(Directory.GetFiles(dir), Has.Length.EqualTo(1), "no temporary file left");
            }
            finally
            {
                Directory.Delete(dir, true);
            }
        }

        [Test]
        public void TheClockIsTheSumOfTheFrameTimesAsTheSolverCountsThem()
        {
            var solver = Solver();
            var recording = new HoldRecording();
            var hand = new HandSample(1, true, true, double.NaN);
            solver.BeginHold(1, 1);
            recording.Begin(solver, in hand);
            foreach (double dt in new[] { 0.01, double.NaN, -0.5, 0.02 })
            {
                solver.Step(in hand, dt);
                recording.Step(solver, in hand, dt);
            }
            Assert.That(recording[0].Time, Is.EqualTo(0));
            Assert.That(recording[2].Time, Is.EqualTo(0.01), "NaN counts as no time");
            Assert.That(recording[3].Time, Is.EqualTo(0.01), "so does a negative frame time");
            Assert.That(recording[4].Time, Is.EqualTo(0.03).Within(1e-15));
            Assert.That(recording.Duration, Is.EqualTo(0.03).Within(1e-15));
        }

        [Test]
        public void ReplayingTheRecordedHandGivesTheRecordedObject()
        {
            // Replay takes tracked as confident; with no low-confidence frames it sees what the solver saw.
            foreach (string profile in NamedProfiles.PipelineNames)
            {
                var recording = Record(Solver(2.0, profile, 0.6), 200, withLosses: false);
                double[] replayed = TraceReplay.Run(Solver(2.0, profile, 0.6), recording.ToTrace());
                for (int i = 0; i < recording.Count; i++)
                    Assert.That(replayed[i], Is.EqualTo(recording[i].ObjectY).Within(1e-9), profile + ", frame " + i);
                Assert.That(recording[recording.Count - 1].ObjectY - 0.8, Is.GreaterThan(0.005), profile + ": the object was lifted (by 0.3 m × W_std/W = 7 mm under gain alone)");
            }
        }

        [Test]
        public void AFullBufferGrowsAndKeepsEveryFrame()
        {
            var recording = Record(Solver(), 10, withLosses: false, new HoldRecording(4));
            Assert.That(recording.Count, Is.EqualTo(10));
            Assert.That(recording.Capacity, Is.EqualTo(16));
            Assert.That(recording.Growths, Is.EqualTo(2));
            for (int i = 0; i < 10; i++) Assert.That(recording[i].Time, Is.EqualTo(i * Dt).Within(1e-12));
            recording.Clear();
            Assert.That(recording.Count, Is.EqualTo(0));
            Assert.That(recording.Capacity, Is.EqualTo(16), "the buffer is kept");
            Assert.Throws<ArgumentOutOfRangeException>(() => { var _ = recording[0]; });
            Assert.Throws<ArgumentOutOfRangeException>(() => new HoldRecording(0));
        }

        [Test]
        public void AProfileNameIsWrittenWithoutCommasQuotesOrLineBreaks()
        {
            var profile = NamedProfiles.Paper.WithLimits(null, "mine, \"v2\"\nfinal");
            var solver = new WeightSolver(WeightModel.FromMass(0.5), profile);
            var recording = new HoldRecording();
            var hand = new HandSample(1);
            solver.BeginHold(1, 1);
            recording.Begin(solver, in hand);
            string row = recording.ToCsv().Split('\n')[1];
            Assert.That(row.Split(','), Has.Length.EqualTo(HoldRecording.Header.Split(',').Length));
            Assert.That(row, Does.Contain(",mine_ _v2__final,"));
        }

        [TestCase("", 1, "empty")]
        [TestCase("time,hand_y\n0,1\n", 1, "missing column 't'")]
        [TestCase("t,y\n0,1\n", 1, "missing column 'hand_y'")]
        [TestCase("t,hand_y,t\n", 1, "appears twice")]
        [TestCase("t,hand_y\n0,1\n\n0.1,abc\n", 4, "hand_y")]
        [TestCase("t,hand_y\n,1\n", 2, "'t' is empty")]
        [TestCase("t,hand_y,tracked\n0,1,yes\n", 2, "tracked")]
        [TestCase("t,hand_y\n0,1,2\n", 2, "expected 2 fields")]
        public void AMalformedRecordingNamesTheLine(string text, int line, string what)
        {
            var e = Assert.Throws<FormatException>(() => HoldRecording.ReadCsv(new StringReader(text), "hold.csv"));
            Assert.That(e.Message, Does.StartWith("hold.csv:" + line + ":").And.Contain(what));
        }

        [Test]
        public void AReplayTraceWithoutTheExtraColumnsReadsToo()
        {
            var r = HoldRecording.ReadCsv(new StringReader("pose_t,hand_y,t\n,0.8,0\n0.03,,0.011\n"), "trace.csv");
            Assert.That(r.Count, Is.EqualTo(2));
            Assert.That(r[0].Tracked && r[0].HighConfidence, Is.True, "tracked by default");
            Assert.That(double.IsNaN(r[0].PoseTime) && double.IsNaN(r[1].HandY) && double.IsNaN(r[0].ObjectY), Is.True);
            Assert.That(r[1].PoseTime, Is.EqualTo(0.03));
            Assert.That(r[1].Time, Is.EqualTo(0.011));
            Assert.That(r[0].Profile, Is.EqualTo(""));
        }

        static void Hold(WeightSolver solver, HoldRecording recording, int count)
        {
            var begin = new HandSample(1, true, true, 0);
            solver.BeginHold(1, 1, 0);
            recording.Begin(solver, in begin);
            for (int i = 1; i < count; i++)
            {
                double t = i / 90.0, poseT = Math.Floor(t * 30) / 30;
                var sample = i % 97 == 0 ? HandSample.Lost : new HandSample(1 + 0.2 * Math.Sin(poseT), true, i % 13 != 0, poseT);
                solver.Step(in sample, 1 / 90.0);
                recording.Step(solver, in sample, 1 / 90.0);
            }
        }

        [Test]
        public void RecordingAFrameAllocatesNothing()
        {
            var solver = Solver(0.7);
            var recording = new HoldRecording(100000);
            Allocation.AssertNone(n => Hold(solver, recording, n), "recorded frames");
#if !UNITY_5_3_OR_NEWER
            Assert.That(recording.Count, Is.EqualTo(100000));
#endif
        }
    }
}
