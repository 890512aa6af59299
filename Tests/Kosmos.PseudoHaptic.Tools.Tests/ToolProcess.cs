using System.Diagnostics;
using System.Runtime.InteropServices;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Runs the built tool (pseudohaptic.dll beside the tests) as a child process: exit code, stdout, stderr and
/// its peak resident memory. The peak is the child's own VmHWM from /proc/self/status, which the tool writes
/// at exit to the file named by PSEUDOHAPTIC_PEAK_RSS_FILE (Cli.PeakMemoryVariable): exact, taken inside the
/// measured process at its end, and independent of /usr/bin/time being installed. Linux only (-1 elsewhere).
/// </summary>
public static class ToolProcess
{
    public sealed record Result(int Code, string Stdout, string Stderr, long PeakKb);

    static string Dll => Path.Combine(AppContext.BaseDirectory, "pseudohaptic.dll");

    // A test run started in the background (`cmd &` in a script) inherits SIGINT ignored, and by POSIX convention the
    // tool then keeps ignoring it, so the SIGINT tests would hang. Where coreutils' env can, the tool is started with
    // SIGINT back at its default, as from a terminal.
    static readonly bool ResetSigint = OperatingSystem.IsLinux() && CanResetSigint();

    static bool CanResetSigint()
    {
        try
        {
            using var p = Process.Start(new ProcessStartInfo("env") { ArgumentList = { "--default-signal=INT", "true" }, UseShellExecute = false, RedirectStandardError = true })!;
            p.WaitForExit(10_000);
            return p.HasExited && p.ExitCode == 0;
        }
        catch (System.ComponentModel.Win32Exception) { return false; }
    }

    public static Process Start(string workingDirectory, IEnumerable<string> args, string? peakFile = null, bool redirectStdin = false)
    {
        var info = new ProcessStartInfo(ResetSigint ? "env" : "dotnet")
        {
            WorkingDirectory = workingDirectory,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            RedirectStandardInput = redirectStdin,
            UseShellExecute = false,
        };
        if (ResetSigint) { info.ArgumentList.Add("--default-signal=INT"); info.ArgumentList.Add("dotnet"); }
        info.ArgumentList.Add(Dll);
        foreach (var a in args) info.ArgumentList.Add(a);
        info.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        if (peakFile != null) info.Environment[Kosmos.PseudoHaptic.Cli.Cli.PeakMemoryVariable] = peakFile;
        return Process.Start(info)!;
    }

    public static Result Run(string workingDirectory, params string[] args) => Run(workingDirectory, TimeSpan.FromSeconds(120), args);

    public static Result Run(string workingDirectory, TimeSpan timeout, params string[] args)
    {
        string peakFile = Path.Combine(Path.GetTempPath(), "ph-peak-" + Guid.NewGuid().ToString("N"));
        using var p = Start(workingDirectory, args, peakFile);
        var stdout = p.StandardOutput.ReadToEndAsync();
        var stderr = p.StandardError.ReadToEndAsync();
        if (!p.WaitForExit(timeout))
        {
            p.Kill(entireProcessTree: true);
            throw new TimeoutException("pseudohaptic " + string.Join(' ', args) + " did not end within " + timeout);
        }
        p.WaitForExit();
        long peak = -1;
        if (File.Exists(peakFile))
        {
            peak = long.Parse(File.ReadAllText(peakFile).Trim(), System.Globalization.CultureInfo.InvariantCulture);
            File.Delete(peakFile);
        }
        return new Result(p.ExitCode, stdout.Result, stderr.Result, peak);
    }

    [DllImport("libc.so.6", EntryPoint = "kill", SetLastError = true)]
    static extern int Kill(int pid, int signal);

    [DllImport("libc.so.6", EntryPoint = "mkfifo", SetLastError = true)]
    static extern int MkFifo([MarshalAs(UnmanagedType.LPUTF8Str)] string path, uint mode);

    public static void Signal(Process p, int signal)
    {
        if (Kill(p.Id, signal) != 0) throw new InvalidOperationException("kill failed: " + Marshal.GetLastPInvokeError());
    }

    public static void MakeFifo(string path)
    {
        if (MkFifo(path, Convert.ToUInt32("644", 8)) != 0) throw new InvalidOperationException("mkfifo failed: " + Marshal.GetLastPInvokeError());
    }

    public static bool IsLinux => OperatingSystem.IsLinux();
}
