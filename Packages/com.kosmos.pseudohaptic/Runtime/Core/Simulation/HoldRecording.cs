using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace Kosmos.PseudoHaptic.Simulation
{
    /// <summary>
    /// The frames of one hold, kept in a preallocated buffer while the hold runs and written afterwards as a
    /// CSV in the replay trace format: <c>pseudohaptic replay</c> reads its <c>t,hand_y,tracked,pose_t</c>
    /// and ignores the other columns (<see cref="Header"/>). Recording a frame copies a few numbers into the
    /// buffer and allocates nothing; only a hold longer than the capacity grows the buffer (doubling it, so
    /// rarely). Writing and reading are for the end of a hold, not for every frame. Not thread-safe.
    /// </summary>
    /// <remarks>
    /// Numbers are written in the invariant culture, round-trippable; NaN as an empty field (no hand while
    /// untracked, unknown pose time); tracked and high_confidence as 1 or 0. The profile name is written as
    /// it is, except that a comma, quote or line break in it becomes '_', so no field is ever quoted.
    /// </remarks>
    public sealed class HoldRecording
    {
        /// <summary>The columns, in order. The first four are the replay trace format's.</summary>
        public const string Header = "t,hand_y,tracked,pose_t,object_y,mass_kg,profile,high_confidence,standard_speed";

        /// <summary>One minute at 90 Hz.</summary>
        public const int DefaultCapacity = 5400;

        static readonly char[] Unsafe = { ',', '"', '\r', '\n' };

        RecordedFrame[] _frames;
        int _count;
        double _time;
        readonly char[] _number = new char[40];

        public HoldRecording(int capacity = DefaultCapacity)
        {
            if (capacity < 1) throw new ArgumentOutOfRangeException(nameof(capacity), "capacity must be at least 1 frame");
            _frames = new RecordedFrame[capacity];
        }

        /// <summary>Frames recorded.</summary>
        public int Count => _count;

        /// <summary>Frames the buffer holds before it must grow.</summary>
        public int Capacity => _frames.Length;

        /// <summary>How often the buffer has grown since it was created (each growth allocates once).</summary>
        public int Growths { get; private set; }

        /// <summary>The hold's clock at the last frame, s.</summary>
        public double Duration => _time;

        /// <summary>The frame at <paramref name="index"/>, 0-based.</summary>
        public RecordedFrame this[int index]
        {
            get
            {
                if ((uint)index >= (uint)_count) throw new ArgumentOutOfRangeException(nameof(index));
                return _frames[index];
            }
        }

        /// <summary>Forgets every frame and resets the clock; keeps the buffer.</summary>
        public void Clear()
        {
            _count = 0;
            _time = 0;
        }

        /// <summary>Appends a frame as given (its time included); grows the buffer when full.</summary>
        public void Add(in RecordedFrame frame)
        {
            if (_count == _frames.Length)
            {
                var bigger = new RecordedFrame[_frames.Length * 2];
                Array.Copy(_frames, bigger, _count);
                _frames = bigger;
                Growths++;
            }
            _frames[_count++] = frame;
            _time = frame.Time;
        }

        /// <summary>
        /// Starts the recording of a hold (forgetting any earlier one) with its first frame at t = 0: the hand as
        /// the solver was given it at <see cref="WeightSolver.BeginHold"/> and the object where the solver put
        /// it. Call right after BeginHold.
        /// </summary>
        public void Begin(WeightSolver solver, in HandSample hand)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            Clear();
            Append(solver, in hand, 0);
        }

        /// <summary>
        /// Records one step: the hand as the solver was given it, the frame time as given (absorbed as the solver
        /// absorbs it: NaN or negative count as no time, infinity as an hour), and the object's new height.
        /// Call right after <see cref="WeightSolver.Step"/>. Allocates nothing.
        /// </summary>
        public void Step(WeightSolver solver, in HandSample hand, double dt)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            if (double.IsPositiveInfinity(dt)) dt = 3600;
            else if (!(dt > 0)) dt = 0;
            Append(solver, in hand, _time + dt);
        }

        void Append(WeightSolver solver, in HandSample hand, double time)
        {
            bool usable = hand.IsTracked && !double.IsNaN(hand.Y) && !double.IsInfinity(hand.Y);
            var frame = new RecordedFrame
            {
                Time = time,
                HandY = usable ? hand.Y : double.NaN,
                Tracked = hand.IsTracked,
                HighConfidence = hand.IsHighConfidence,
                PoseTime = hand.PoseTime,
                ObjectY = solver.ObjectY,
                MassKg = solver.Model.MassKg,
                StandardSpeed = solver.StandardSpeed,
                Profile = solver.Profile.Name,
            };
            Add(in frame);
        }

        /// <summary>The replay trace of the recording: one <see cref="TraceFrame"/> per frame.</summary>
        public TraceFrame[] ToTrace()
        {
            var trace = new TraceFrame[_count];
            for (int i = 0; i < _count; i++) trace[i] = _frames[i].ToTraceFrame();
            return trace;
        }

        /// <summary>Writes the header and one row per frame, lines ending in '\n'.</summary>
        public void WriteCsv(TextWriter writer)
        {
            if (writer == null) throw new ArgumentNullException(nameof(writer));
            writer.Write(Header);
            writer.Write('\n');
            for (int i = 0; i < _count; i++)
            {
                ref readonly RecordedFrame f = ref _frames[i];
                Number(writer, f.Time); writer.Write(',');
                Number(writer, f.HandY); writer.Write(',');
                writer.Write(f.Tracked ? '1' : '0'); writer.Write(',');
                Number(writer, f.PoseTime); writer.Write(',');
                Number(writer, f.ObjectY); writer.Write(',');
                Number(writer, f.MassKg); writer.Write(',');
                Name(writer, f.Profile); writer.Write(',');
                writer.Write(f.HighConfidence ? '1' : '0'); writer.Write(',');
                Number(writer, f.StandardSpeed);
                writer.Write('\n');
            }
        }

        /// <summary>The whole CSV as a string (for small recordings and tests).</summary>
        public string ToCsv()
        {
            var writer = new StringWriter(CultureInfo.InvariantCulture);
            WriteCsv(writer);
            return writer.ToString();
        }

        void Number(TextWriter writer, double value)
        {
            if (double.IsNaN(value)) return;
            if (value.TryFormat(new Span<char>(_number), out int length, "R", CultureInfo.InvariantCulture))
                writer.Write(_number, 0, length);
            else
                writer.Write(value.ToString("R", CultureInfo.InvariantCulture));
        }

        static void Name(TextWriter writer, string name)
        {
            if (string.IsNullOrEmpty(name)) return;
            if (name.IndexOfAny(Unsafe) < 0) { writer.Write(name); return; }
            for (int i = 0; i < name.Length; i++)
                writer.Write(Array.IndexOf(Unsafe, name[i]) >= 0 ? '_' : name[i]);
        }

        /// <summary>
        /// Reads a recording back: columns by name in any order, <c>t</c> and <c>hand_y</c> required, the others
        /// optional (absent or empty numbers read as NaN; tracked defaults to 1, high_confidence to tracked);
        /// blank lines skipped. A fault throws <see cref="FormatException"/> naming
        /// <paramref name="sourceName"/> and the line (the header is line 1).
        /// </summary>
        public static HoldRecording ReadCsv(TextReader reader, string sourceName)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            string header = reader.ReadLine();
            if (header == null) throw Error(sourceName, 1, "the file is empty; expected the header " + Header);
            if (header.Length > 0 && header[0] == '\uFEFF') header = header.Substring(1);
            string[] names = header.Split(',');
            var column = new Dictionary<string, int>(StringComparer.Ordinal);
            for (int i = 0; i < names.Length; i++)
            {
                string name = Field(names[i]);
                if (name.Length == 0) continue;
                if (column.ContainsKey(name)) throw Error(sourceName, 1, "column '" + name + "' appears twice");
                column.Add(name, i);
            }
            int t = Column(column, "t"), handY = Column(column, "hand_y");
            if (t < 0) throw Error(sourceName, 1, "missing column 't'");
            if (handY < 0) throw Error(sourceName, 1, "missing column 'hand_y'");
            int tracked = Column(column, "tracked"), poseT = Column(column, "pose_t"), objectY = Column(column, "object_y"),
                mass = Column(column, "mass_kg"), profile = Column(column, "profile"), confidence = Column(column, "high_confidence"),
                speed = Column(column, "standard_speed");

            var recording = new HoldRecording(64);
            int line = 1;
            string text;
            while ((text = reader.ReadLine()) != null)
            {
                line++;
                if (text.Trim().Length == 0) continue;
                string[] fields = text.Split(',');
                if (fields.Length != names.Length)
                    throw Error(sourceName, line, "expected " + names.Length + " fields, found " + fields.Length);
                var frame = new RecordedFrame
                {
                    Time = Number(fields, t, "t", false, sourceName, line),
                    HandY = Number(fields, handY, "hand_y", true, sourceName, line),
                    Tracked = Flag(fields, tracked, "tracked", true, sourceName, line),
                    PoseTime = Number(fields, poseT, "pose_t", true, sourceName, line),
                    ObjectY = Number(fields, objectY, "object_y", true, sourceName, line),
                    MassKg = Number(fields, mass, "mass_kg", true, sourceName, line),
                    StandardSpeed = Number(fields, speed, "standard_speed", true, sourceName, line),
                    Profile = profile >= 0 ? Field(fields[profile]) : "",
                };
                frame.HighConfidence = Flag(fields, confidence, "high_confidence", frame.Tracked, sourceName, line);
                recording.Add(in frame);
            }
            return recording;
        }

        static int Column(Dictionary<string, int> columns, string name) => columns.TryGetValue(name, out int i) ? i : -1;

        static string Field(string raw)
        {
            string s = raw.Trim();
            return s.Length >= 2 && s[0] == '"' && s[s.Length - 1] == '"' ? s.Substring(1, s.Length - 2) : s;
        }

        static double Number(string[] fields, int index, string name, bool emptyIsNaN, string source, int line)
        {
            if (index < 0) return double.NaN;
            string s = Field(fields[index]);
            if (s.Length == 0)
            {
                if (emptyIsNaN) return double.NaN;
                throw Error(source, line, "column '" + name + "' is empty");
            }
            if (!double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double value))
                throw Error(source, line, "column '" + name + "': cannot parse '" + s + "' as a number");
            return value;
        }

        static bool Flag(string[] fields, int index, string name, bool fallback, string source, int line)
        {
            if (index < 0) return fallback;
            string s = Field(fields[index]);
            if (s.Length == 0) return fallback;
            if (s == "1" || s.Equals("true", StringComparison.OrdinalIgnoreCase)) return true;
            if (s == "0" || s.Equals("false", StringComparison.OrdinalIgnoreCase)) return false;
            throw Error(source, line, "column '" + name + "': expected 1 or 0, found '" + s + "'");
        }

        static FormatException Error(string source, int line, string reason)
            => new FormatException((string.IsNullOrEmpty(source) ? "<recording>" : source) + ":" + line.ToString(CultureInfo.InvariantCulture) + ": " + reason);
    }
}
