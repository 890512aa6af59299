using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Traces;

/// <summary>
/// Trace rows waiting in order, in bounded memory: the first <see cref="InMemory"/> in a list, the rest in a
/// temporary file (".ph" + 8 hex + ".tmp" in the given folder, 98 bytes a row), deleted when drained,
/// disposed, or the process is stopped by SIGINT/SIGTERM.
/// </summary>
public sealed class FrameBuffer(string folder) : IDisposable
{
    public const int InMemory = 4096;

    readonly List<TraceRow> _memory = new();
    string? _path;
    FileStream? _file;
    BinaryWriter? _writer;
    long _spilled;

    public long Count => _memory.Count + _spilled;

    public void Add(in TraceRow r)
    {
        if (_memory.Count < InMemory && _spilled == 0) { _memory.Add(r); return; }
        if (_writer == null)
        {
            _path = Kosmos.PseudoHaptic.Evaluation.AtomicFile.TemporaryPath(folder);
            Temporaries.Create(_path, p => _file = new FileStream(p, FileMode.CreateNew, FileAccess.ReadWrite, FileShare.None, 65536, FileOptions.DeleteOnClose));
            _writer = new BinaryWriter(_file!);
        }
        _writer.Write(r.First.Time);
        _writer.Write(r.First.HandY);
        _writer.Write(r.First.Tracked);
        _writer.Write(r.First.PoseTime);
        _writer.Write(r.HandX);
        _writer.Write(r.HandZ);
        _writer.Write(r.Hand2X);
        _writer.Write(r.Hand2Y);
        _writer.Write(r.Hand2Z);
        _writer.Write(r.Tracked2);
        _writer.Write(r.Pose2T);
        _writer.Write(r.Rig.X);
        _writer.Write(r.Rig.Y);
        _writer.Write(r.Rig.Z);
        _writer.Write(r.Rig.YawDegrees);
        _spilled++;
    }

    /// <summary>Hands every frame to <paramref name="write"/> in order, then empties the buffer.</summary>
    public void Drain(Action<TraceRow> write)
    {
        foreach (var f in _memory) write(f);
        _memory.Clear();
        if (_writer != null && _file != null)
        {
            _writer.Flush();
            _file.Position = 0;
            using (var reader = new BinaryReader(_file, System.Text.Encoding.UTF8, leaveOpen: true))
                for (long i = 0; i < _spilled; i++)
                {
                    var r = new TraceRow { First = new TraceFrame(reader.ReadDouble(), reader.ReadDouble(), reader.ReadBoolean(), reader.ReadDouble()) };
                    r.HandX = reader.ReadDouble();
                    r.HandZ = reader.ReadDouble();
                    r.Hand2X = reader.ReadDouble();
                    r.Hand2Y = reader.ReadDouble();
                    r.Hand2Z = reader.ReadDouble();
                    r.Tracked2 = reader.ReadBoolean();
                    r.Pose2T = reader.ReadDouble();
                    r.Rig = new RigFrame(reader.ReadDouble(), reader.ReadDouble(), reader.ReadDouble(), reader.ReadDouble());
                    write(r);
                }
        }
        Close();
    }

    void Close()
    {
        _writer?.Dispose();
        _file?.Dispose();
        _writer = null;
        _file = null;
        _spilled = 0;
        if (_path != null) Temporaries.Delete(_path);
        _path = null;
    }

    public void Dispose() => Close();
}
