// Test double of UnityEngine's yield instructions (UnityCsReference 2022.3 Runtime/Export/Scripting/YieldInstruction.cs,
// WaitForFixedUpdate.cs, WaitForSeconds.cs), as a [UnityTest] yields them; the runner (UnityEngine.TestRunner/) reads them.
namespace UnityEngine
{
    public class YieldInstruction
    {
    }

    public sealed class WaitForFixedUpdate : YieldInstruction
    {
    }

    public sealed class WaitForSeconds : YieldInstruction
    {
        internal readonly float Seconds;

        public WaitForSeconds(float seconds) => Seconds = seconds;
    }
}
