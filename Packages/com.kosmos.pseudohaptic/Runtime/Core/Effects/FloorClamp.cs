using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1, confinement condition 2: the object's local y never goes below 0 (P5).
    /// Acts on the final height, after the speed limit, so nothing can push the object through. It keeps the
    /// object's bottom, <see cref="WeightSolver.BottomBelowPivot"/> below its pivot, on or above the floor.
    /// </summary>
    public sealed class FloorClamp : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("floor-clamp", EffectStage.Position, typeof(FloorClamp),
            "§3.1, confinement condition 2",
            "the object's bottom stays on or above the floor (its local y never below it)",
            s => new FloorClamp(s[0]),
            SettingDescriptor.Number<FloorClamp>("floor", "m", 0, -WeightSolver.MaxCoordinate, WeightSolver.MaxCoordinate, "lowest local height", e => e.Floor));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        /// <summary>Lowest local height, m.</summary>
        public double Floor { get; }

        public FloorClamp(double floor = 0)
        {
            Floor = Descriptor.Settings[0].Check(floor);
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            // NewObjectY is the held height (pivot + grab offset): the pivot's lowest height moves with it.
            double lowest = Floor + constants.BottomBelowPivot + state.GrabOffset;
            if (frame.NewObjectY < lowest) frame.NewObjectY = lowest;
        }

        /// <summary>A function of the height it is given and the grab: the same height gets the same answer.</summary>
        protected internal override bool IsStill(in HoldState state, in SolverConstants constants) => true;
    }
}
