using System;
using System.IO;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>A fresh folder under the temporary path for one test, deleted with everything in it when disposed.</summary>
    internal sealed class TempFolder : IDisposable
    {
        public string Path { get; }

        public TempFolder(string prefix)
        {
            Path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), prefix + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Path);
        }

        /// <summary>The path of <paramref name="name"/> in the folder.</summary>
        public string File(string name) => System.IO.Path.Combine(Path, name);

        public void Dispose() => Directory.Delete(Path, true);
    }
}
