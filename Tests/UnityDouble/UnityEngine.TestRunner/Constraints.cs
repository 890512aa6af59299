// Test double of the Unity Test Framework 1.1.33's constraints (UnityEngine.TestRunner/Assertions/Is.cs,
// ConstraintsExtensions.cs, AllocatingGCMemoryConstraint.cs): the same type relationships as the real ones
// (UnityEngine.TestTools.Constraints.Is derives from NUnit.Framework.Is, so a file importing both namespaces finds `Is`
// ambiguous, CS0104, as Unity's compiler does). The allocation is measured here with the GC's per-thread counter,
// where the Test Framework uses Unity's profiler recorder.
using System;
using NUnit.Framework;
using NUnit.Framework.Constraints;

namespace UnityEngine.TestTools.Constraints
{
    public class Is : NUnit.Framework.Is
    {
        public static AllocatingGCMemoryConstraint AllocatingGCMemory() => new AllocatingGCMemoryConstraint();
    }

    public static class ConstraintExtensions
    {
        public static AllocatingGCMemoryConstraint AllocatingGCMemory(this ConstraintExpression chain)
        {
            var constraint = new AllocatingGCMemoryConstraint();
            chain.Append(constraint);
            return constraint;
        }
    }

    public class AllocatingGCMemoryConstraint : Constraint
    {
        public override ConstraintResult ApplyTo<TActual>(TActual actual)
        {
            if (!(actual is TestDelegate code)) throw new ArgumentException("The actual value must be a TestDelegate.");
            long before = GC.GetAllocatedBytesForCurrentThread();
            code();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            return new ConstraintResult(this, allocated, allocated > 0);
        }

        public override ConstraintResult ApplyTo<TActual>(ActualValueDelegate<TActual> del) => ApplyTo<object>((TestDelegate)(() => del()));

        public override string Description => "allocates GC memory";
    }
}
