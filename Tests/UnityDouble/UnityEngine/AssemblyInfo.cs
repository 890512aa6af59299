// The double's other assemblies (compiled one by one under their real names by the compile check) use the engine's
// internals; the package's assemblies never can.
using System.Runtime.CompilerServices;

[assembly: InternalsVisibleTo("UnityEditor")]
[assembly: InternalsVisibleTo("UnityEngine.TestRunner")]
[assembly: InternalsVisibleTo("Oculus.VR")]
[assembly: InternalsVisibleTo("Oculus.Interaction")]
[assembly: InternalsVisibleTo("Unity.XR.Hands")]
[assembly: InternalsVisibleTo("Unity.XR.CoreUtils")]
[assembly: InternalsVisibleTo("Unity.XR.Management")]
[assembly: InternalsVisibleTo("Unity.XR.Management.Editor")]
[assembly: InternalsVisibleTo("Oculus.VR.Editor")]
