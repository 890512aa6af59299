using System;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>One rendered frame of a scripted hand as a Quest 2 reports it.</summary>
    internal struct HandFrame
    {
        public double Time, Dt;
        public Vector3d Position;
        public bool Tracked, HighConfidence;
        public double Pinch;
    }

    /// <summary>
    /// A scripted hand as a Quest 2 reports it: frames at <see cref="FrameRate"/>, poses at 30 Hz, 45 ms late,
    /// confidence that drops in fast motion, a pinch strength that flickers, one-pose glitches and tracking
    /// losses where asked. The path is given as a function of time (true hand).
    /// </summary>
    internal sealed class QuestHand
    {
        public double FrameRate = 90, PoseRate = 30, Latency = 0.045;
        public double PinchFlicker = 0.1;
        public int Seed = 1;
        public Func<double, Vector3d> Path = t => new Vector3d(0, 0.8, 0);
        public Func<double, double> Pinch = t => 1;
        readonly System.Collections.Generic.List<(double from, double to)> _losses = new System.Collections.Generic.List<(double, double)>();
        readonly System.Collections.Generic.List<double> _glitches = new System.Collections.Generic.List<double>();

        public QuestHand Lose(double from, double seconds) { _losses.Add((from, from + seconds)); return this; }
        public QuestHand Glitch(double at) { _glitches.Add(at); return this; }

        public HandFrame[] Render(double seconds)
        {
            var random = new Random(Seed);
            int n = (int)Math.Ceiling(seconds * FrameRate);
            var frames = new HandFrame[n];
            double posePeriod = 1 / PoseRate;
            for (int i = 0; i < n; i++)
            {
                double t = (i + 1) / FrameRate;
                double sampled = Math.Floor((t - Latency) / posePeriod) * posePeriod; // the last pose delivered, sampled 45 ms earlier
                if (sampled < 0) sampled = 0;
                bool lost = false;
                foreach (var (from, to) in _losses) lost |= t >= from && t < to;
                Vector3d p = Path(sampled);
                foreach (double g in _glitches)
                    if (sampled <= g && g < sampled + posePeriod) p += new Vector3d(0, 0.15, 0); // one wrong pose
                double speed = (Path(sampled + 0.01) - Path(sampled)).Length / 0.01;
                double pinch = Pinch(t) + PinchFlicker * (random.NextDouble() * 2 - 1);
                frames[i] = new HandFrame
                {
                    Time = t,
                    Dt = 1 / FrameRate,
                    Position = lost ? Vector3d.NaN : p,
                    Tracked = !lost,
                    HighConfidence = !lost && !(speed > 1.0 && random.NextDouble() < 0.5),
                    Pinch = Math.Max(0, Math.Min(1, pinch)),
                };
            }
            return frames;
        }

        /// <summary>Minimum-jerk profile from 0 to 1 over u in [0, 1].</summary>
        public static double MinimumJerk(double u)
        {
            u = Math.Min(1, Math.Max(0, u));
            return u * u * u * (10 - 15 * u + 6 * u * u);
        }

        /// <summary>A lift from <paramref name="start"/> by <paramref name="rise"/> m between <paramref name="t0"/> and <paramref name="t0"/> + <paramref name="seconds"/>.</summary>
        public static Func<double, Vector3d> Lift(Vector3d start, double rise, double t0, double seconds) =>
            t => start + new Vector3d(0, rise * MinimumJerk((t - t0) / seconds), 0);
    }

    /// <summary>An engine-free scene for the grab logic: boxes in world space with unit-scale parents at the origin.</summary>
    internal sealed class BoxScene : IGrabCandidates
    {
        public sealed class Box : IParentSpace
        {
            public Vector3d Position;
            public Vector3d HalfSize = new Vector3d(0.05, 0.05, 0.05);
            public HeldObject Hold;
            public Box(Vector3d position, double massKg, WeightProfile profile = null)
            {
                Position = position;
                Hold = new HeldObject(this);
                Hold.Configure(WeightModel.FromMass(massKg), profile ?? NamedProfiles.Paper, 0.5);
            }
            public double HeightOf(Vector3d world) => world.Y;
            public Vector3d ClosestPoint(Vector3d p) => new Vector3d(
                Math.Max(Position.X - HalfSize.X, Math.Min(Position.X + HalfSize.X, p.X)),
                Math.Max(Position.Y - HalfSize.Y, Math.Min(Position.Y + HalfSize.Y, p.Y)),
                Math.Max(Position.Z - HalfSize.Z, Math.Min(Position.Z + HalfSize.Z, p.Z)));
        }

        public readonly System.Collections.Generic.List<Box> Boxes = new System.Collections.Generic.List<Box>();
        public Box Add(Vector3d position, double massKg = 1, WeightProfile profile = null) { var b = new Box(position, massKg, profile); Boxes.Add(b); return b; }
        public int Count => Boxes.Count;
        public Vector3d ClosestPoint(int index, Vector3d hand) => Boxes[index].ClosestPoint(hand);
        public int HandsOn(int index) => Boxes[index].Hold.HandCount;
    }

    /// <summary>What PinchGrab does, engine-free: one hand's driver over a <see cref="BoxScene"/>.</summary>
    internal sealed class ScriptedGrab : IGrabDriver
    {
        public readonly int Id;
        public readonly BoxScene Scene;
        public readonly HandGrab Grab = new HandGrab();
        public readonly HandDrawing Drawing = new HandDrawing();
        public HandDrawingMode Mode = HandDrawingMode.HandTrue;
        public BoxScene.Box Held;
        public double Reach = 0.06;
        public bool BreakAway;
        public int Follows, LostFollows;
        HandFrame _frame;
        Vector3d _grabOffset;

        public ScriptedGrab(BoxScene scene, int id = 1) { Scene = scene; Id = id; }

        public Vector3d DrawnOffset { get; private set; }

        public void Tick(in HandFrame frame)
        {
            _frame = frame;
            Grab.Tick(frame.Tracked, frame.Pinch, frame.Dt, this);
            Vector3d lag = Held != null ? GrabFollow.Lag(Held.Position, frame.Position, _grabOffset) : Vector3d.Zero;
            DrawnOffset = Drawing.Update(Mode, Held != null, lag, frame.Dt);
        }

        public bool TryGrab()
        {
            int i = GrabSelection.Nearest(_frame.Position, Reach, HeldObject.MaxHands, Scene);
            if (i < 0) return false;
            BoxScene.Box b = Scene.Boxes[i];
            if (!b.Hold.Begin(Id, _frame.Position, double.NaN, b.Position, b.Position.Y)) return false;
            Held = b;
            _grabOffset = b.Position - _frame.Position;
            b.Position = new Vector3d(b.Position.X, b.Hold.Solver.ObjectY, b.Position.Z);
            return true;
        }

        public bool IsStillHeld => Held != null && Held.Hold.Holds(Id);
        public bool BrokeAway => BreakAway || (Held != null && Held.Hold.BrokeAway);

        public void Follow(bool tracked)
        {
            Follows++;
            if (!tracked) LostFollows++;
            Held.Position = GrabFollow.Horizontal(Held.Position, _frame.Position, _grabOffset, tracked, GrabFollow.GrabMovesHorizontal(true, Held.Hold));
            double y = Held.Hold.Step(Id, _frame.Position, tracked, _frame.HighConfidence, double.NaN, _frame.Dt);
            Held.Position = Held.Hold.Horizontal(Held.Position);
            if (!double.IsNaN(y)) Held.Position = new Vector3d(Held.Position.X, y, Held.Position.Z);
            Held.Hold.TrackObject(Held.Position);
        }

        public void Release()
        {
            Held?.Hold.End(Id);
            Held = null;
        }
    }
}
