using System.Buffers.Binary;
using System.Text;

namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>
/// A PNG's tEXt chunks (ISO/IEC 15948 §11.3.4.3): a keyword and a Latin-1 text a viewer ignores. Used to record
/// what a generated chart was made from, read back before it is regenerated.
/// </summary>
public static class PngText
{
    static readonly byte[] Signature = { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A };

    /// <summary>The PNG with a tEXt chunk (keyword, text) after its IHDR chunk.</summary>
    public static byte[] With(byte[] png, string keyword, string text)
    {
        if (!IsPng(png)) throw new ArgumentException("not a PNG", nameof(png));
        byte[] data = Encoding.Latin1.GetBytes(keyword + "\0" + text);
        int ihdrEnd = 8 + 12 + BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(8));
        var chunk = new byte[12 + data.Length];
        BinaryPrimitives.WriteInt32BigEndian(chunk, data.Length);
        Encoding.ASCII.GetBytes("tEXt").CopyTo(chunk, 4);
        data.CopyTo(chunk, 8);
        BinaryPrimitives.WriteUInt32BigEndian(chunk.AsSpan(8 + data.Length), Crc32(chunk.AsSpan(4, 4 + data.Length)));
        return png[..ihdrEnd].Concat(chunk).Concat(png[ihdrEnd..]).ToArray();
    }

    /// <summary>The text of the first tEXt chunk with <paramref name="keyword"/>, or null.</summary>
    public static string? Read(byte[] png, string keyword)
    {
        if (!IsPng(png)) return null;
        int at = 8;
        while (at + 12 <= png.Length)
        {
            int length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(at));
            if (length < 0 || at + 12 + (long)length > png.Length) return null;
            string type = Encoding.ASCII.GetString(png, at + 4, 4);
            if (type == "IEND" || type == "IDAT") return null;
            if (type == "tEXt")
            {
                string body = Encoding.Latin1.GetString(png, at + 8, length);
                int zero = body.IndexOf('\0');
                if (zero > 0 && body[..zero] == keyword) return body[(zero + 1)..];
            }
            at += 12 + length;
        }
        return null;
    }

    static bool IsPng(byte[] png) => png.Length > 33 && png.AsSpan(0, 8).SequenceEqual(Signature) && Encoding.ASCII.GetString(png, 12, 4) == "IHDR";

    static uint Crc32(ReadOnlySpan<byte> bytes)
    {
        uint crc = 0xFFFFFFFF;
        foreach (byte b in bytes)
        {
            crc ^= b;
            for (int k = 0; k < 8; k++) crc = (crc & 1) != 0 ? 0xEDB88320 ^ (crc >> 1) : crc >> 1;
        }
        return ~crc;
    }
}
