using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using System.Threading;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// strace attached to this very test process (every thread), so a test sees the system calls the code under test
    /// makes in-process, as it runs: the same code a mutation tool swaps in, unlike a child process that loads its own
    /// copy. Linux only, and only where strace is installed and may trace (root, or ptrace allowed); elsewhere (a Unity
    /// editor on Windows or macOS) the test is ignored with the reason. <c>-y</c> shows each descriptor's path.
    /// </summary>
    sealed class SelfTrace : IDisposable
    {
        readonly Process _strace;
        readonly string _file;
        bool _stopped;

        SelfTrace(Process strace, string file) { _strace = strace; _file = file; }

        /// <summary>Attaches strace tracing <paramref name="syscalls"/> (strace's <c>-e trace=</c>), with <paramref name="inject"/>
        /// (<c>-e inject=</c>) if given, only the calls on <paramref name="path"/> (<c>-P</c>) if given, and returns once this
        /// thread is traced.</summary>
        public static SelfTrace Start(string folder, string syscalls, string inject = null, string path = null)
        {
            if (!RuntimeInformation.IsOSPlatform(OSPlatform.Linux)) Assert.Ignore("strace: Linux only");
            string strace = new[] { "/usr/bin/strace", "/bin/strace", "/usr/local/bin/strace" }.FirstOrDefault(File.Exists);
            if (strace == null) Assert.Ignore("strace is not installed (.ci/run installs it)");
            if (TracerOfThisThread() != 0) Assert.Ignore("this process is already traced (a debugger?)");
            string file = Path.Combine(folder, "self-" + Guid.NewGuid().ToString("N").Substring(0, 8) + ".strace");
            var info = new ProcessStartInfo(strace)
            {
                Arguments = "-f -qq -y -o \"" + file + "\" -e trace=" + syscalls + (inject != null ? " -e inject=" + inject : "") + (path != null ? " -P \"" + path + "\"" : "")
                    + " -p " + Process.GetCurrentProcess().Id.ToString(CultureInfo.InvariantCulture),
                UseShellExecute = false,
                RedirectStandardError = true,
                RedirectStandardOutput = true,
            };
            var p = Process.Start(info);
            var trace = new SelfTrace(p, file);
            var clock = Stopwatch.StartNew();
            while (TracerOfThisThread() == 0)
            {
                if (p.HasExited)
                    Assert.Ignore("strace cannot attach here: " + p.StandardError.ReadToEnd().Trim());
                if (clock.ElapsedMilliseconds > 20000)
                {
                    trace.Dispose();
                    Assert.Ignore("strace did not attach within 20 s");
                }
                Thread.Sleep(5);
            }
            return trace;
        }

        /// <summary>Runs <paramref name="act"/> traced (<see cref="Start"/>, the trace in <paramref name="folder"/>) and returns
        /// the calls on <paramref name="under"/> (its own path or below it), each as "fsync PATH", "rename FROM -> TO",
        /// "mkdir PATH", with " = -1" appended to a failed one.</summary>
        public static List<string> CallsUnder(Action act, string folder, string syscalls, string under, string inject = null)
        {
            List<Call> calls;
            using (var trace = Start(folder, syscalls, inject))
            {
                try { act(); }
                finally { calls = trace.Stop(); }
            }
            var shown = new List<string>();
            foreach (var c in calls)
            {
                string[] paths = c.Name.StartsWith("fsync", StringComparison.Ordinal) || c.Name == "fdatasync" ? new[] { c.DescriptorPath } : c.Paths;
                if (paths.Length == 0 || paths[0] == null || !(paths[0] == under || paths[0].StartsWith(under + "/", StringComparison.Ordinal))) continue;
                string name = c.Name.StartsWith("rename", StringComparison.Ordinal) ? "rename" : c.Name.StartsWith("mkdir", StringComparison.Ordinal) ? "mkdir" : c.Name;
                shown.Add(name + " " + string.Join(" -> ", paths) + (c.Result < 0 ? " = -1" : ""));
            }
            return shown;
        }

        /// <summary>Detaches strace (SIGINT, as a user's Ctrl-C) and returns the calls it saw.</summary>
        public List<Call> Stop()
        {
            Detach();
            return Parse(File.ReadAllLines(_file));
        }

        /// <summary>
        /// The completed calls of strace's output lines. With -f, a call another thread interrupts is printed in two
        /// lines, "1234 fsync(5&lt;/a&gt; &lt;unfinished ...&gt;" and later "1234 &lt;... fsync resumed&gt;) = 0": they are
        /// joined, so a call is never lost because the machine was busy (this test process's other threads).
        /// </summary>
        public static List<Call> Parse(IEnumerable<string> lines)
        {
            var calls = new List<Call>();
            var unfinished = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (string raw in lines)
            {
                string line = raw;
                var u = Unfinished.Match(line);
                if (u.Success)
                {
                    unfinished[u.Groups[1].Value] = u.Groups[1].Value + " " + u.Groups[2].Value;
                    continue;
                }
                var r = Resumed.Match(line);
                if (r.Success)
                {
                    if (!unfinished.TryGetValue(r.Groups[1].Value, out string head)) continue;
                    unfinished.Remove(r.Groups[1].Value);
                    line = head + r.Groups[2].Value;
                }
                var m = Complete.Match(line);
                if (m.Success) calls.Add(new Call(m.Groups[1].Value, m.Groups[2].Value, long.Parse(m.Groups[3].Value, CultureInfo.InvariantCulture)));
            }
            return calls;
        }

        void Detach()
        {
            if (_stopped) return;
            _stopped = true;
            if (!_strace.HasExited)
            {
                using (var kill = Process.Start(new ProcessStartInfo("kill", "-INT " + _strace.Id.ToString(CultureInfo.InvariantCulture)) { UseShellExecute = false }))
                    kill.WaitForExit(10000);
                if (!_strace.WaitForExit(20000)) _strace.Kill();
            }
            var clock = Stopwatch.StartNew();
            while (TracerOfThisThread() != 0 && clock.ElapsedMilliseconds < 10000) Thread.Sleep(5);
        }

        public void Dispose()
        {
            Detach();
            _strace.Dispose();
        }

        static int TracerOfThisThread()
        {
            foreach (string line in File.ReadAllLines("/proc/thread-self/status"))
                if (line.StartsWith("TracerPid:", StringComparison.Ordinal))
                    return int.Parse(line.Substring(10).Trim(), CultureInfo.InvariantCulture);
            return 0;
        }

        // "1234 fsync(5</tmp/x/.ph0a1b2c3d.tmp>) = 0", "1234 rename(\"/tmp/x/a\", \"/tmp/x/b\") = 0", "… = -1 EIO (…) (INJECTED)".
        static readonly Regex Complete = new Regex(@"^\d+\s+(\w+)\((.*)\)\s+=\s+(-?\d+)");
        // "1234 openat(AT_FDCWD, \"/tmp/x\", O_RDONLY|O_CLOEXEC <unfinished ...>" and "1234 <... openat resumed>) = 5</tmp/x>".
        static readonly Regex Unfinished = new Regex(@"^(\d+)\s+(.*?)\s*<unfinished \.\.\.>$");
        static readonly Regex Resumed = new Regex(@"^(\d+)\s+<\.\.\. \w+ resumed>(.*)$");

        /// <summary>One completed call: its name, its arguments as strace prints them, its result (−1 on an error).</summary>
        public sealed class Call
        {
            public readonly string Name, Args;
            public readonly long Result;
            public Call(string name, string args, long result) { Name = name; Args = args; Result = result; }

            /// <summary>The path of a call on a descriptor (<c>fsync(5&lt;/a/b&gt;)</c>), or null.</summary>
            public string DescriptorPath
            {
                get
                {
                    int open = Args.IndexOf('<'), close = Args.LastIndexOf('>');
                    return open >= 0 && close > open ? Args.Substring(open + 1, close - open - 1) : null;
                }
            }

            /// <summary>The quoted paths of the call (a rename's source and destination).</summary>
            public string[] Paths
            {
                get
                {
                    var found = Regex.Matches(Args, "\"((?:[^\"\\\\]|\\\\.)*)\"");
                    var paths = new string[found.Count];
                    for (int i = 0; i < paths.Length; i++) paths[i] = found[i].Groups[1].Value;
                    return paths;
                }
            }

            public override string ToString() => Name + "(" + Args + ") = " + Result;
        }
    }
}
