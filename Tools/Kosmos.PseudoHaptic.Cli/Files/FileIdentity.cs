using System.Runtime.InteropServices;

namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>What a path names, following symbolic links.</summary>
public enum FileKind { Missing, Regular, Folder, Fifo, CharacterDevice, BlockDevice, Socket, Other }

/// <summary>
/// What a path names and which file it is, by identity rather than spelling: device and inode from
/// <c>statx(2)</c> on Linux (a layout that is the same on every architecture) or <c>stat(2)</c> on macOS,
/// following symbolic links, so relative spellings, <c>./</c>, symbolic and hard links of one file compare
/// equal. Where neither call is available (Windows), the identity is the full path with links resolved,
/// compared without case.
/// </summary>
public readonly record struct FileIdentity(FileKind Kind, ulong Device, ulong Inode, string? FullPath)
{
    public bool Exists => Kind != FileKind.Missing;

    /// <summary>The same existing file or folder.</summary>
    public bool SameAs(FileIdentity other)
    {
        if (!Exists || !other.Exists) return false;
        if (FullPath == null && other.FullPath == null) return Device == other.Device && Inode == other.Inode;
        return FullPath != null && other.FullPath != null && string.Equals(FullPath, other.FullPath, StringComparison.OrdinalIgnoreCase);
    }

    public static FileIdentity Of(string path)
    {
        if (string.IsNullOrEmpty(path)) return new FileIdentity(FileKind.Missing, 0, 0, null);
        if (Native.TryStat(path, out var identity)) return identity;
        return Fallback(path);
    }

    static FileIdentity Fallback(string path)
    {
        string full;
        try
        {
            full = Path.GetFullPath(path);
            var target = File.ResolveLinkTarget(full, returnFinalTarget: true);
            if (target != null) full = target.FullName;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            return new FileIdentity(FileKind.Missing, 0, 0, null);
        }
        if (Directory.Exists(full)) return new FileIdentity(FileKind.Folder, 0, 0, Path.TrimEndingDirectorySeparator(full));
        if (File.Exists(full)) return new FileIdentity(FileKind.Regular, 0, 0, full);
        return new FileIdentity(FileKind.Missing, 0, 0, null);
    }

    static class Native
    {
        const int AtFdCwd = -100;
        const uint StatxType = 0x1, StatxMode = 0x2, StatxIno = 0x100;
        static bool _unavailable = !(OperatingSystem.IsLinux() || OperatingSystem.IsMacOS());

        [DllImport("libc.so.6", EntryPoint = "statx", SetLastError = true)]
        static extern int Statx(int dirfd, [MarshalAs(UnmanagedType.LPUTF8Str)] string path, int flags, uint mask, [Out] byte[] buffer);

        [DllImport("libSystem.B.dylib", EntryPoint = "stat$INODE64", SetLastError = true)]
        static extern int StatMacX64([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [Out] byte[] buffer);

        [DllImport("libSystem.B.dylib", EntryPoint = "stat", SetLastError = true)]
        static extern int StatMac([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [Out] byte[] buffer);

        public static bool TryStat(string path, out FileIdentity identity)
        {
            identity = default;
            if (_unavailable || path.IndexOf('\0') >= 0) return false;
            var buffer = new byte[512];
            try
            {
                int mode;
                ulong device, inode;
                if (OperatingSystem.IsLinux())
                {
                    if (Statx(AtFdCwd, path, 0, StatxType | StatxMode | StatxIno, buffer) != 0) return Missing(out identity);
                    // struct statx: stx_mode (u16) at 28, stx_ino (u64) at 32, stx_dev_major/minor (u32) at 136/140.
                    mode = BitConverter.ToUInt16(buffer, 28);
                    inode = BitConverter.ToUInt64(buffer, 32);
                    device = ((ulong)BitConverter.ToUInt32(buffer, 136) << 32) | BitConverter.ToUInt32(buffer, 140);
                }
                else
                {
                    int rc = RuntimeInformation.ProcessArchitecture == Architecture.X64 ? StatMacX64(path, buffer) : StatMac(path, buffer);
                    if (rc != 0) return Missing(out identity);
                    // struct stat (64-bit inodes): st_dev (i32) at 0, st_mode (u16) at 4, st_ino (u64) at 8.
                    device = BitConverter.ToUInt32(buffer, 0);
                    mode = BitConverter.ToUInt16(buffer, 4);
                    inode = BitConverter.ToUInt64(buffer, 8);
                }
                var kind = (mode & 0xF000) switch
                {
                    0x8000 => FileKind.Regular,
                    0x4000 => FileKind.Folder,
                    0x1000 => FileKind.Fifo,
                    0x2000 => FileKind.CharacterDevice,
                    0x6000 => FileKind.BlockDevice,
                    0xC000 => FileKind.Socket,
                    _ => FileKind.Other,
                };
                identity = new FileIdentity(kind, device, inode, null);
                return true;
            }
            catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
            {
                _unavailable = true;
                return false;
            }
        }

        static bool Missing(out FileIdentity identity)
        {
            identity = new FileIdentity(FileKind.Missing, 0, 0, null);
            return true;
        }
    }
}
