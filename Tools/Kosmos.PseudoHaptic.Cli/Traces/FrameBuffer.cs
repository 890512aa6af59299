using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Traces;

/// <summary>
/// Frames waiting in order, in bounded memory: the first <see cref="InMemory"/> in a list, the rest in a
/// temporary file (".ph" + 8 hex + ".tmp" in the given folder, 25 bytes a frame), deleted when drained,
/// disposed, or the process is stopped by SIGINT/SIGTERM.
/// </summary>
public sealed class FrameBuffer(string folder) : IDisposable
{
    public const int InMemory = 4096;

    readonly List<TraceFrame> _memory = new();
    string? _path;
    FileStream? _file;
    BinaryWriter? _writer;
    long _spilled;

    public long Count => _memory.Count + _spilled;

    public void Add(in TraceFrame f)
    {
        if (_memory.Count < InMemory && _spilled == 0) { _memory.Add(f); return; }
        if (_writer == null)
        {
            _path = Kosmos.PseudoHaptic.Evaluation.AtomicFile.TemporaryPath(folder);
            Temporaries.Track(_path);
            _file = new FileStream(_path, FileMode.CreateNew, FileAccess.ReadWrite, FileShare.None, 65536, FileOptions.DeleteOnClose);
            _writer = new BinaryWriter(_file);
        }
        _writer.Write(f.Time);
        _writer.Write(f.HandY);
        _writer.Write(f.Tracked);
        _writer.Write(f.PoseTime);
        _spilled++;
    }

    /// <summary>Hands every frame to <paramref name="write"/> in order, then empties the buffer.</summary>
    public void Drain(Action<TraceFrame> write)
    {
        foreach (var f in _memory) write(f);
        _memory.Clear();
        if (_writer != null && _file != null)
        {
            _writer.Flush();
            _file.Position = 0;
            using (var reader = new BinaryReader(_file, System.Text.Encoding.UTF8, leaveOpen: true))
                for (long i = 0; i < _spilled; i++)
                    write(new TraceFrame(reader.ReadDouble(), reader.ReadDouble(), reader.ReadBoolean(), reader.ReadDouble()));
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
