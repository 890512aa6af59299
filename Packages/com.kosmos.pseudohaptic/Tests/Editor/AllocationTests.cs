using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>P10: steady-state updates allocate nothing.</summary>
    public class AllocationTests
    {
        static void Steps(WeightSolver solver, int count)
        {
            for (int i = 0; i < count; i++)
            {
                double t = i / 90.0, poseT = Math.Floor(t * 30) / 30;
                var sample = i % 97 == 0 ? HandSample.Lost : new HandSample(1 + 0.2 * Math.Sin(poseT), true, i % 13 != 0, poseT);
                solver.Step(sample, 1 / 90.0);
            }
        }

        [TestCase("paper"), TestCase("paper-experiment"), TestCase("gain")]
        public void StepAllocatesNothing(string profile)
        {
            var solver = new WeightSolver(WeightModel.FromMass(0.7), NamedProfiles.Get(profile).With(new OffsetRelaxation(), "all"));
            solver.BeginHold(1, 1, 0);
            Allocation.AssertNone(n => Steps(solver, n), "steps");
        }
    }
}
