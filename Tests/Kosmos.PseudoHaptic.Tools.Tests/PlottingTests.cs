using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;
using Kosmos.PseudoHaptic.Cli.Plotting;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

[TestFixture]
public sealed class PlottingTests
{
    private static readonly byte[] PngSignature = { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A };
    private static readonly Rgb Red = new(220, 20, 30);

    // ---- PNG container ----

    [Test]
    public void Png_StartsWithSignature()
    {
        byte[] png = new Raster(3, 2).ToPng();

        Assert.That(png.Take(8).ToArray(), Is.EqualTo(PngSignature));
    }

    [Test]
    public void Png_IhdrHoldsSizeAndRgb8Format()
    {
        byte[] png = new LineChart(321, 123).ToPng();
        List<Chunk> chunks = ReadChunks(png);

        Assert.That(chunks[0].Type, Is.EqualTo("IHDR"));
        byte[] ihdr = chunks[0].Data;
        Assert.That(ihdr, Has.Length.EqualTo(13));
        Assert.That(BinaryPrimitives.ReadInt32BigEndian(ihdr.AsSpan(0)), Is.EqualTo(321), "width");
        Assert.That(BinaryPrimitives.ReadInt32BigEndian(ihdr.AsSpan(4)), Is.EqualTo(123), "height");
        Assert.That(ihdr[8], Is.EqualTo(8), "bit depth");
        Assert.That(ihdr[9], Is.EqualTo(2), "colour type (truecolour)");
        Assert.That(ihdr[12], Is.EqualTo(0), "interlace");
        Assert.That(chunks[^1].Type, Is.EqualTo("IEND"));
        Assert.That(chunks[^1].Data, Is.Empty);
    }

    [Test]
    public void Png_EveryChunkCrcIsValid()
    {
        var chart = new LineChart(200, 150) { Title = "crc" };
        chart.AddLine(new double[] { 0, 1, 2 }, new double[] { 1, 0, 1 }, Palette.Get(0), "a");
        byte[] png = chart.ToPng();

        List<Chunk> chunks = ReadChunks(png);

        Assert.That(chunks.Select(c => c.Type), Is.EqualTo(new[] { "IHDR", "IDAT", "IEND" }));
        foreach (Chunk chunk in chunks)
        {
            uint expected = BitwiseCrc32(Encoding.ASCII.GetBytes(chunk.Type).Concat(chunk.Data).ToArray());
            Assert.That(chunk.Crc, Is.EqualTo(expected), chunk.Type);
        }

        Assert.That(chunks[^1].Crc, Is.EqualTo(0xAE426082u), "the well-known CRC of an IEND chunk");
    }

    [Test]
    public void Png_IdatInflatesToOneFilterByteAndThreeBytesPerPixelPerRow()
    {
        const int Width = 97, Height = 41;
        byte[] png = new LineChart(Width, Height).ToPng();

        byte[] raw = Inflate(png);

        Assert.That(raw, Has.Length.EqualTo(Height * (1 + 3 * Width)));
        for (int y = 0; y < Height; y++)
        {
            Assert.That(raw[y * (1 + 3 * Width)], Is.EqualTo(0), $"filter type of row {y}");
        }
    }

    [Test]
    public void Png_RoundTripsThePixels()
    {
        var raster = new Raster(17, 9);
        raster.SetPixel(0, 0, Red);
        raster.SetPixel(16, 8, new Rgb(1, 2, 3));
        raster.FillRect(5, 3, 4, 2, Palette.Get(2));

        byte[] decoded = DecodeRgb(raster.ToPng(), out int width, out int height);

        Assert.That((width, height), Is.EqualTo((17, 9)));
        Assert.That(decoded, Is.EqualTo(raster.Pixels.ToArray()));
    }

    [Test]
    public void Png_RejectsABufferOfTheWrongSize()
    {
        Assert.That(() => PngWriter.Encode(4, 4, new byte[4 * 4 * 3 - 1]), Throws.ArgumentException);
    }

    [Test]
    public void Crc32_MatchesTheStandardCheckValue()
    {
        Assert.That(Crc32.Compute(Encoding.ASCII.GetBytes("123456789")), Is.EqualTo(0xCBF43926u));
        Assert.That(Crc32.Compute(ReadOnlySpan<byte>.Empty), Is.EqualTo(0u));
        Assert.That(Crc32.Append(Crc32.Compute("1234"u8), "56789"u8), Is.EqualTo(0xCBF43926u));
    }

    // ---- Raster ----

    [Test]
    public void Raster_HorizontalLineOfThicknessTwoFillsTwoRowsBetweenItsEnds()
    {
        var raster = new Raster(64, 40);

        raster.DrawLine(10, 20, 50, 20, Red, 2);

        Assert.That(raster.GetPixel(30, 19), Is.EqualTo(Red));
        Assert.That(raster.GetPixel(30, 20), Is.EqualTo(Red));
        Assert.That(raster.GetPixel(30, 18), Is.EqualTo(Rgb.White));
        Assert.That(raster.GetPixel(30, 21), Is.EqualTo(Rgb.White));
        Assert.That(raster.GetPixel(5, 20), Is.EqualTo(Rgb.White), "left of the start");
        Assert.That(raster.GetPixel(55, 20), Is.EqualTo(Rgb.White), "right of the end");
    }

    [Test]
    public void Raster_DiagonalLinePassesThroughItsMidpoint()
    {
        var raster = new Raster(50, 50);

        raster.DrawLine(5, 5, 45, 45, Red, 2);

        Assert.That(raster.GetPixel(25, 25), Is.EqualTo(Red));
        Assert.That(raster.GetPixel(40, 10), Is.EqualTo(Rgb.White));
    }

    [Test]
    public void Raster_ClipKeepsDrawingInsideAndHugeOrNonFiniteCoordinatesAreHarmless()
    {
        var raster = new Raster(40, 40);
        raster.SetClip(10, 10, 20, 20);

        Assert.That(() =>
        {
            raster.DrawLine(-1e12, 20, 1e12, 20, Red, 2);
            raster.DrawLine(double.NaN, 0, 5, 5, Red, 2);
            raster.DrawLine(0, 0, double.PositiveInfinity, 5, Red, 2);
            raster.FillCircle(double.NaN, 3, 4, Red);
            double phase = 0;
            raster.DrawDashedLine(-1e12, 25, 1e12, 25, Red, 2, 8, 6, ref phase);
        }, Throws.Nothing);
        Assert.That(raster.GetPixel(20, 20), Is.EqualTo(Red), "inside the clip");
        Assert.That(raster.GetPixel(5, 20), Is.EqualTo(Rgb.White), "left of the clip");
        Assert.That(raster.GetPixel(35, 20), Is.EqualTo(Rgb.White), "right of the clip");
    }

    [Test]
    public void Raster_DashedLineLeavesGaps()
    {
        var raster = new Raster(100, 10);
        double phase = 0;

        raster.DrawDashedLine(0, 5, 100, 5, Red, 2, 8, 6, ref phase);

        int red = Enumerable.Range(0, 100).Count(x => raster.GetPixel(x, 5) == Red);
        int white = Enumerable.Range(0, 100).Count(x => raster.GetPixel(x, 5) == Rgb.White);
        Assert.That(red, Is.GreaterThan(40));
        Assert.That(white, Is.GreaterThan(15));
    }

    // ---- Font ----

    [Test]
    public void BitmapFont_EveryPrintableCharacterButSpaceHasInk()
    {
        for (char c = '!'; c <= '~'; c++)
        {
            bool any = false;
            for (int col = 0; col < BitmapFont.GlyphWidth; col++)
            {
                for (int row = 0; row < BitmapFont.GlyphHeight; row++)
                {
                    any |= BitmapFont.IsSet(c, col, row);
                }
            }

            Assert.That(any, Is.True, $"glyph for '{c}'");
        }
    }

    [Test]
    public void BitmapFont_DrawsOnlyInsideItsMeasuredBox()
    {
        const string Text = "height (m) -1.5e-9 kg_%";
        const int Scale = 2, X = 3, Y = 4;
        int w = BitmapFont.MeasureWidth(Text, Scale), h = BitmapFont.MeasureHeight(Scale);
        var raster = new Raster(w + 10, h + 10);

        BitmapFont.DrawText(raster, X, Y, Text, Rgb.Black, Scale);

        int inside = 0, outside = 0;
        for (int y = 0; y < raster.Height; y++)
        {
            for (int x = 0; x < raster.Width; x++)
            {
                if (raster.GetPixel(x, y) == Rgb.White) continue;
                bool inBox = x >= X && x < X + w && y >= Y && y < Y + h;
                if (inBox) inside++;
                else outside++;
            }
        }

        Assert.That(inside, Is.GreaterThan(100));
        Assert.That(outside, Is.Zero);
        Assert.That(BitmapFont.MeasureWidth("ab", 2), Is.EqualTo((2 * BitmapFont.Advance - 1) * 2));
    }

    [Test]
    public void BitmapFont_DrawsCommonNonAsciiAsLookAlikes()
    {
        Assert.That(BitmapFont.Displayed('\u2212'), Is.EqualTo('-'), "minus sign");
        Assert.That(BitmapFont.Displayed('\u00D7'), Is.EqualTo('x'));
        Assert.That(BitmapFont.Displayed('\u00B5'), Is.EqualTo('u'));
        Assert.That(BitmapFont.Displayed('\u4E2D'), Is.EqualTo('?'));
        Assert.That(BitmapFont.Displayed('A'), Is.EqualTo('A'));
    }

    // ---- Ticks ----

    [TestCase(1.0, 5)]
    [TestCase(0.37, 8)]
    [TestCase(1234.5, 7)]
    [TestCase(3e-7, 4)]
    [TestCase(99.0, 10)]
    [TestCase(2.0, 2)]
    public void AxisTicks_StepIsOneTwoOrFiveTimesAPowerOfTen(double span, int target)
    {
        double step = AxisTicks.NiceStep(span, target);
        double mantissa = step / Math.Pow(10, Math.Floor(Math.Log10(step) + 1e-9));

        Assert.That(new[] { 1.0, 2.0, 5.0 }.Any(m => Math.Abs(mantissa - m) < 1e-6), Is.True, $"step {step}");
        Assert.That(span / step, Is.LessThanOrEqualTo(target + 1e-9));
        Assert.That(span / step, Is.GreaterThan(target / 5.0 - 1e-9), "not needlessly coarse");
    }

    [Test]
    public void AxisTicks_LabelsAreTidy()
    {
        IReadOnlyList<double> ticks = AxisTicks.Linear(-0.3, 0.45, 0.1);

        Assert.That(ticks.Select(v => AxisTicks.FormatLinear(v, 0.1)),
            Is.EqualTo(new[] { "-0.3", "-0.2", "-0.1", "0.0", "0.1", "0.2", "0.3", "0.4" }));
        Assert.That(AxisTicks.FormatLinear(250, 50), Is.EqualTo("250"));
        Assert.That(AxisTicks.Decades(3, 2000, 10), Is.EqualTo(new[] { 10.0, 100.0, 1000.0 }));
        Assert.That(AxisTicks.FormatLog(1e-9), Is.EqualTo("1e-9"));
        Assert.That(AxisTicks.FormatLog(0.01), Is.EqualTo("0.01"));
        Assert.That(AxisTicks.FormatLog(1000), Is.EqualTo("1000"));
    }

    // ---- Chart ----

    [Test]
    public void LineChart_DrawsTheLineWhereTheDataMaps()
    {
        var chart = new LineChart(400, 300) { XMin = 0, XMax = 10, YMin = 0, YMax = 10, Title = "t", XLabel = "x", YLabel = "y" };
        chart.AddLine(new double[] { 0, 10 }, new double[] { 5, 5 }, Red, "flat");

        Raster raster = chart.Render();
        (double px, double py) = chart.DataToPixel(5, 5);
        (double qx, double qy) = chart.DataToPixel(5, 8);
        (double leftX, _) = chart.DataToPixel(0, 0);
        (double rightX, _) = chart.DataToPixel(10, 0);

        Assert.That(raster.GetPixel((int)px, (int)py), Is.EqualTo(Red));
        Assert.That(raster.GetPixel((int)qx, (int)qy), Is.Not.EqualTo(Red));
        Assert.That(leftX, Is.GreaterThan(0).And.LessThan(rightX));
        Assert.That(rightX, Is.LessThan(400));

        byte[] decoded = DecodeRgb(chart.ToPng(), out int width, out _);
        int i = ((int)py * width + (int)px) * 3;
        Assert.That(new Rgb(decoded[i], decoded[i + 1], decoded[i + 2]), Is.EqualTo(Red), "same pixel in the PNG");
    }

    [Test]
    public void LineChart_NaNBreaksTheLineWithoutThrowing()
    {
        double[] xs = Enumerable.Range(0, 11).Select(i => (double)i).ToArray();
        double[] ys = xs.Select(x => x == 5 ? double.NaN : 5.0).ToArray();
        var chart = new LineChart(400, 300) { XMin = 0, XMax = 10, YMin = 0, YMax = 10 };
        chart.AddLine(xs, ys, Red, "gappy");

        Raster raster = null!;
        Assert.That(() => raster = chart.Render(), Throws.Nothing);

        (double gx, double gy) = chart.DataToPixel(5, 5);
        (double sx, double sy) = chart.DataToPixel(2.5, 5);
        Assert.That(raster.GetPixel((int)gx, (int)gy), Is.Not.EqualTo(Red), "gap at the NaN");
        Assert.That(raster.GetPixel((int)sx, (int)sy), Is.EqualTo(Red), "line elsewhere");
    }

    [Test]
    public void LineChart_DegenerateDataDoesNotThrow()
    {
        var chart = new LineChart(300, 200) { Title = "odd", XLabel = "x", YLabel = "y" };
        chart.AddLine(Array.Empty<double>(), Array.Empty<double>(), Palette.Get(0), "empty");
        chart.AddLine(new[] { double.NaN, double.NaN }, new[] { 1.0, 2.0 }, Palette.Get(1), "all NaN");
        chart.AddLine(new[] { 1.0, 2.0, double.PositiveInfinity, 4.0 }, new[] { 1.0, double.NegativeInfinity, 3.0, 4.0 }, Palette.Get(2), "inf");
        chart.AddLine(new[] { 3.0 }, new[] { 3.0 }, Palette.Get(3), "single");
        chart.AddPoints(new[] { 1.0, 1.0 }, new[] { 2.0, double.NaN }, Palette.Get(4), "pts", new[] { "a", null });
        chart.AddLine(new[] { 0.0, 1.0 }, new[] { 1e308, -1e308 }, Palette.Get(5), "huge", dashed: true);

        Assert.That(() => chart.ToPng(), Throws.Nothing);

        var constant = new LineChart(300, 200);
        constant.AddLine(new[] { 2.0, 2.0 }, new[] { 7.0, 7.0 }, Palette.Get(0), "constant");
        Assert.That(() => constant.ToPng(), Throws.Nothing);

        var log = new LineChart(300, 200) { LogX = true };
        log.AddPoints(new[] { 0.0, -5.0, 120.0, 4e4 }, new[] { 1.0, 2.0, 3.0, 0.5 }, Palette.Get(0), "log");
        Assert.That(() => log.ToPng(), Throws.Nothing);

        var tiny = new LineChart(8, 6) { Title = "much too long a title", XLabel = "x", YLabel = "y" };
        tiny.AddLine(new[] { 0.0, 1.0 }, new[] { 0.0, 1.0 }, Palette.Get(0), "tiny");
        Assert.That(tiny.ToPng(), Has.Length.GreaterThan(8));
    }

    [Test]
    public void LineChart_WithoutDataStillDrawsAxes()
    {
        var chart = new LineChart(300, 200) { Title = "nothing yet" };

        byte[] decoded = DecodeRgb(chart.ToPng(), out int width, out int height);

        Assert.That((width, height), Is.EqualTo((300, 200)));
        int dark = 0;
        for (int i = 0; i < decoded.Length; i += 3)
        {
            if (decoded[i] < 0x80 && decoded[i + 1] < 0x80 && decoded[i + 2] < 0x80) dark++;
        }

        Assert.That(dark, Is.GreaterThan(2 * (width + height) / 2), "frame, ticks and labels");
    }

    [Test]
    public void LineChart_LogXSpacesDecadesEqually()
    {
        var chart = new LineChart(600, 400) { LogX = true };
        chart.AddPoints(new[] { 10.0, 1000.0 }, new[] { 1.0, 2.0 }, Palette.Get(0), "p", new[] { "ten", "thousand" });
        chart.Render();

        double x10 = chart.DataToPixel(10, 1).X, x100 = chart.DataToPixel(100, 1).X, x1000 = chart.DataToPixel(1000, 1).X;

        Assert.That(x100 - x10, Is.EqualTo(x1000 - x100).Within(1e-9));
        Assert.That(x100 - x10, Is.GreaterThan(50));
    }

    [Test]
    public void LineChart_RejectsMismatchedArrays()
    {
        var chart = new LineChart();

        Assert.That(() => chart.AddLine(new double[3], new double[2], Palette.Get(0), "bad"), Throws.ArgumentException);
        Assert.That(() => chart.AddPoints(new double[2], new double[2], Palette.Get(0), "bad", new[] { "only one" }),
            Throws.ArgumentException);
        Assert.That(() => chart.DataToPixel(0, 0), Throws.InvalidOperationException, "nothing rendered yet");
    }

    [Test]
    public void LineChart_SaveWritesAPngFile()
    {
        string path = Path.Combine(Path.GetTempPath(), $"plotting-test-{Guid.NewGuid():N}", "chart.png");
        var chart = new LineChart(120, 80);
        chart.AddLine(new[] { 0.0, 1.0 }, new[] { 0.0, 1.0 }, Palette.Get(0), "line");
        try
        {
            chart.Save(path);

            Assert.That(File.ReadAllBytes(path).Take(8).ToArray(), Is.EqualTo(PngSignature));
        }
        finally
        {
            Directory.Delete(Path.GetDirectoryName(path)!, recursive: true);
        }
    }

    [Test]
    public void Palette_WrapsAroundForAnyIndex()
    {
        Assert.That(Palette.Get(Palette.Count), Is.EqualTo(Palette.Get(0)));
        Assert.That(Palette.Get(-1), Is.EqualTo(Palette.Get(Palette.Count - 1)));
        Assert.That(Enumerable.Range(0, Palette.Count).Select(Palette.Get).Distinct().Count(), Is.EqualTo(Palette.Count));
    }

    // ---- A minimal PNG reader, written independently of the writer ----

    private sealed record Chunk(string Type, byte[] Data, uint Crc);

    private static List<Chunk> ReadChunks(byte[] png)
    {
        Assert.That(png.Take(8).ToArray(), Is.EqualTo(PngSignature), "signature");
        var chunks = new List<Chunk>();
        int offset = 8;
        while (offset < png.Length)
        {
            int length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(offset));
            string type = Encoding.ASCII.GetString(png, offset + 4, 4);
            byte[] data = png.AsSpan(offset + 8, length).ToArray();
            uint crc = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(offset + 8 + length));
            chunks.Add(new Chunk(type, data, crc));
            offset += 12 + length;
        }

        Assert.That(offset, Is.EqualTo(png.Length), "chunks end exactly at the end of the file");
        return chunks;
    }

    private static byte[] Inflate(byte[] png)
    {
        byte[] idat = ReadChunks(png).Where(c => c.Type == "IDAT").SelectMany(c => c.Data).ToArray();
        using var zlib = new ZLibStream(new MemoryStream(idat), CompressionMode.Decompress);
        using var raw = new MemoryStream();
        zlib.CopyTo(raw);
        return raw.ToArray();
    }

    /// <summary>RGB pixels of a filter-type-0, 8-bit truecolour PNG.</summary>
    private static byte[] DecodeRgb(byte[] png, out int width, out int height)
    {
        byte[] ihdr = ReadChunks(png)[0].Data;
        width = BinaryPrimitives.ReadInt32BigEndian(ihdr.AsSpan(0));
        height = BinaryPrimitives.ReadInt32BigEndian(ihdr.AsSpan(4));
        byte[] raw = Inflate(png);
        int stride = 3 * width;
        var rgb = new byte[height * stride];
        for (int y = 0; y < height; y++)
        {
            Assert.That(raw[y * (stride + 1)], Is.EqualTo(0), "filter type");
            Array.Copy(raw, y * (stride + 1) + 1, rgb, y * stride, stride);
        }

        return rgb;
    }

    private static uint BitwiseCrc32(byte[] data)
    {
        uint crc = 0xFFFFFFFF;
        foreach (byte b in data)
        {
            crc ^= b;
            for (int k = 0; k < 8; k++)
            {
                crc = (crc & 1) != 0 ? (crc >> 1) ^ 0xEDB88320 : crc >> 1;
            }
        }

        return ~crc;
    }
}
