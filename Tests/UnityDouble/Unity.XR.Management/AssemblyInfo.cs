// Test double (state in memory).
using System.Runtime.CompilerServices;

[assembly: InternalsVisibleTo("Unity.XR.Management.Editor")]
