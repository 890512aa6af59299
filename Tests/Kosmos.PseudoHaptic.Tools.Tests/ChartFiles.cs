using System.Buffers.Binary;
using System.Text;
using System.Xml.Linq;
using NUnit.Framework;
using SkiaSharp;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// What every chart file the tools write must be: present, a PNG of the stated size (read from its IHDR, not
/// trusted from a decoder), decodable, and not blank (many colours, some ink but mostly background).
/// </summary>
public static class ChartFiles
{
    static readonly byte[] PngSignature = { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A };

    /// <summary>Width and height from the IHDR chunk, which must be the first chunk after the signature.</summary>
    public static (int Width, int Height) IhdrSize(byte[] png)
    {
        Assert.That(png.Length, Is.GreaterThan(33), "too short for a PNG");
        Assert.That(png.Take(8), Is.EqualTo(PngSignature), "PNG signature");
        Assert.That(BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(8)), Is.EqualTo(13), "IHDR length");
        Assert.That(Encoding.ASCII.GetString(png, 12, 4), Is.EqualTo("IHDR"), "first chunk");
        return (BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(16)), BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(20)));
    }

    /// <summary>Asserts the file is a non-blank PNG of (width, height), or of any size when they are null.</summary>
    public static void AssertPng(string path, int? width = null, int? height = null)
    {
        Assert.That(File.Exists(path), Is.True, path + " exists");
        byte[] png = File.ReadAllBytes(path);
        var (w, h) = IhdrSize(png);
        if (width != null) Assert.That(w, Is.EqualTo(width), path + " width");
        if (height != null) Assert.That(h, Is.EqualTo(height), path + " height");

        using var bitmap = SKBitmap.Decode(png);
        Assert.That(bitmap, Is.Not.Null, path + " decodes");
        Assert.That((bitmap.Width, bitmap.Height), Is.EqualTo((w, h)), "decoded size agrees with IHDR");
        var (colours, inkShare) = Ink(bitmap);
        Assert.That(colours, Is.GreaterThanOrEqualTo(16), path + ": distinct colours (a blank or one-colour image has 1)");
        Assert.That(inkShare, Is.InRange(0.01, 0.75), path + ": share of non-white pixels");
    }

    /// <summary>Distinct colours, and the share of pixels that are not white.</summary>
    public static (int Colours, double InkShare) Ink(SKBitmap bitmap)
    {
        var colours = new HashSet<uint>();
        long ink = 0;
        for (int y = 0; y < bitmap.Height; y++)
        for (int x = 0; x < bitmap.Width; x++)
        {
            SKColor c = bitmap.GetPixel(x, y);
            colours.Add((uint)c);
            if (c.Red < 245 || c.Green < 245 || c.Blue < 245) ink++;
        }
        return (colours.Count, (double)ink / ((long)bitmap.Width * bitmap.Height));
    }

    /// <summary>Asserts the file is an SVG document of (width, height) with some drawing in it.</summary>
    public static void AssertSvg(string path, int? width = null, int? height = null)
    {
        Assert.That(File.Exists(path), Is.True, path + " exists");
        var root = XDocument.Load(path).Root!;
        Assert.That(root.Name.LocalName, Is.EqualTo("svg"));
        if (width != null) Assert.That(double.Parse(root.Attribute("width")!.Value.Replace("px", ""), System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(width.Value), "svg width");
        if (height != null) Assert.That(double.Parse(root.Attribute("height")!.Value.Replace("px", ""), System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(height.Value), "svg height");
        Assert.That(root.Descendants().Count(), Is.GreaterThan(10), "svg has drawing elements");
    }
}
