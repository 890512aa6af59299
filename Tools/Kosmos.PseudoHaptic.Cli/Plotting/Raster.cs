namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>
/// An RGB pixel buffer (top-left origin, 3 bytes per pixel) with anti-aliased lines and circles.
/// Pixel (i, j) covers the square [i, i+1) x [j, j+1); shapes take continuous coordinates, so a line of
/// thickness 2 along y = 10.0 fills rows 9 and 10 exactly. All drawing respects the clip rectangle.
/// </summary>
public sealed class Raster
{
    /// <summary>Largest width or height accepted (keeps the buffer well inside an array's limits).</summary>
    public const int MaxSide = 16384;

    private readonly byte[] _rgb;
    private int _clipLeft, _clipTop, _clipRight, _clipBottom; // right and bottom exclusive

    public Raster(int width, int height) : this(width, height, Rgb.White)
    {
    }

    public Raster(int width, int height, Rgb background)
    {
        if (width <= 0 || width > MaxSide) throw new ArgumentOutOfRangeException(nameof(width), width, $"Width must be 1..{MaxSide}.");
        if (height <= 0 || height > MaxSide) throw new ArgumentOutOfRangeException(nameof(height), height, $"Height must be 1..{MaxSide}.");
        Width = width;
        Height = height;
        _rgb = new byte[width * height * 3];
        ResetClip();
        Clear(background);
    }

    public int Width { get; }

    public int Height { get; }

    /// <summary>The pixels, row-major, top row first, R G B per pixel.</summary>
    public ReadOnlySpan<byte> Pixels => _rgb;

    /// <summary>Restricts all later drawing to the given rectangle (intersected with the raster).</summary>
    public void SetClip(int x, int y, int width, int height)
    {
        _clipLeft = Math.Clamp(x, 0, Width);
        _clipTop = Math.Clamp(y, 0, Height);
        _clipRight = (int)Math.Clamp((long)x + Math.Max(0, width), _clipLeft, Width);
        _clipBottom = (int)Math.Clamp((long)y + Math.Max(0, height), _clipTop, Height);
    }

    /// <summary>Lets drawing reach the whole raster again.</summary>
    public void ResetClip()
    {
        _clipLeft = 0;
        _clipTop = 0;
        _clipRight = Width;
        _clipBottom = Height;
    }

    /// <summary>Fills the whole raster, ignoring the clip.</summary>
    public void Clear(Rgb colour)
    {
        for (int i = 0; i < _rgb.Length; i += 3)
        {
            _rgb[i] = colour.R;
            _rgb[i + 1] = colour.G;
            _rgb[i + 2] = colour.B;
        }
    }

    public Rgb GetPixel(int x, int y)
    {
        if ((uint)x >= (uint)Width || (uint)y >= (uint)Height)
        {
            throw new ArgumentOutOfRangeException(nameof(x), $"({x}, {y}) lies outside {Width}x{Height}.");
        }

        int i = (y * Width + x) * 3;
        return new Rgb(_rgb[i], _rgb[i + 1], _rgb[i + 2]);
    }

    /// <summary>Sets one pixel; outside the clip it is silently ignored.</summary>
    public void SetPixel(int x, int y, Rgb colour) => BlendPixel(x, y, colour, 1.0);

    /// <summary>Paints <paramref name="colour"/> over one pixel at opacity <paramref name="alpha"/> (0..1).</summary>
    public void BlendPixel(int x, int y, Rgb colour, double alpha)
    {
        if (x < _clipLeft || x >= _clipRight || y < _clipTop || y >= _clipBottom || !(alpha > 0)) return;
        int i = (y * Width + x) * 3;
        if (alpha >= 1)
        {
            _rgb[i] = colour.R;
            _rgb[i + 1] = colour.G;
            _rgb[i + 2] = colour.B;
            return;
        }

        Rgb mixed = new Rgb(_rgb[i], _rgb[i + 1], _rgb[i + 2]).Blend(colour, alpha);
        _rgb[i] = mixed.R;
        _rgb[i + 1] = mixed.G;
        _rgb[i + 2] = mixed.B;
    }

    /// <summary>Fills whole pixels x..x+width-1, y..y+height-1.</summary>
    public void FillRect(int x, int y, int width, int height, Rgb colour)
    {
        int x0 = Math.Max(x, _clipLeft), y0 = Math.Max(y, _clipTop);
        int x1 = (int)Math.Min((long)x + width, _clipRight), y1 = (int)Math.Min((long)y + height, _clipBottom);
        for (int py = y0; py < y1; py++)
        {
            for (int px = x0; px < x1; px++)
            {
                BlendPixel(px, py, colour, 1.0);
            }
        }
    }

    /// <summary>A one-pixel outline just inside the rectangle x..x+width-1, y..y+height-1.</summary>
    public void DrawRect(int x, int y, int width, int height, Rgb colour)
    {
        if (width <= 0 || height <= 0) return;
        FillRect(x, y, width, 1, colour);
        FillRect(x, y + height - 1, width, 1, colour);
        FillRect(x, y, 1, height, colour);
        FillRect(x + width - 1, y, 1, height, colour);
    }

    /// <summary>An anti-aliased line with round caps. Non-finite coordinates draw nothing.</summary>
    public void DrawLine(double x0, double y0, double x1, double y1, Rgb colour, double thickness = 2.0)
    {
        if (!(thickness > 0)) return;
        double half = thickness / 2;
        double reach = half + 1;
        if (!ClipSegment(ref x0, ref y0, ref x1, ref y1,
                _clipLeft - reach, _clipTop - reach, _clipRight + reach, _clipBottom + reach))
        {
            return;
        }

        double dx = x1 - x0, dy = y1 - y0;
        double lengthSquared = dx * dx + dy * dy;
        if (lengthSquared < 1e-12)
        {
            FillCircle(x0, y0, half, colour);
            return;
        }

        double length = Math.Sqrt(lengthSquared);
        if (Math.Abs(dy) >= Math.Abs(dx))
        {
            // Steep: walk rows; in each row only the pixels near the centre line can be covered.
            double span = reach * length / Math.Abs(dy) + reach;
            int rowFrom = Math.Max(_clipTop, (int)Math.Floor(Math.Min(y0, y1) - reach));
            int rowTo = Math.Min(_clipBottom - 1, (int)Math.Ceiling(Math.Max(y0, y1) + reach));
            for (int row = rowFrom; row <= rowTo; row++)
            {
                double t = Math.Clamp((row + 0.5 - y0) / dy, 0, 1);
                double xc = x0 + t * dx;
                int colFrom = Math.Max(_clipLeft, (int)Math.Floor(xc - span));
                int colTo = Math.Min(_clipRight - 1, (int)Math.Ceiling(xc + span));
                for (int col = colFrom; col <= colTo; col++)
                {
                    CoverSegmentPixel(col, row, x0, y0, dx, dy, lengthSquared, half, colour);
                }
            }
        }
        else
        {
            double span = reach * length / Math.Abs(dx) + reach;
            int colFrom = Math.Max(_clipLeft, (int)Math.Floor(Math.Min(x0, x1) - reach));
            int colTo = Math.Min(_clipRight - 1, (int)Math.Ceiling(Math.Max(x0, x1) + reach));
            for (int col = colFrom; col <= colTo; col++)
            {
                double t = Math.Clamp((col + 0.5 - x0) / dx, 0, 1);
                double yc = y0 + t * dy;
                int rowFrom = Math.Max(_clipTop, (int)Math.Floor(yc - span));
                int rowTo = Math.Min(_clipBottom - 1, (int)Math.Ceiling(yc + span));
                for (int row = rowFrom; row <= rowTo; row++)
                {
                    CoverSegmentPixel(col, row, x0, y0, dx, dy, lengthSquared, half, colour);
                }
            }
        }
    }

    /// <summary>
    /// A dashed line: <paramref name="dashOn"/> pixels drawn, <paramref name="dashOff"/> skipped. <paramref name="phase"/>
    /// is the distance already travelled into the pattern; it is updated so a polyline's dashes run on across joints.
    /// </summary>
    public void DrawDashedLine(double x0, double y0, double x1, double y1, Rgb colour, double thickness,
        double dashOn, double dashOff, ref double phase)
    {
        if (!(dashOn > 0) || !(dashOff >= 0))
        {
            DrawLine(x0, y0, x1, y1, colour, thickness);
            return;
        }

        double period = dashOn + dashOff;
        double ox0 = x0, oy0 = y0;
        double fullLength = Math.Sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0));
        double reach = thickness / 2 + 1;
        if (!double.IsFinite(fullLength) ||
            !ClipSegment(ref x0, ref y0, ref x1, ref y1, _clipLeft - reach, _clipTop - reach, _clipRight + reach, _clipBottom + reach))
        {
            if (double.IsFinite(fullLength)) phase = (phase + fullLength) % period;
            return;
        }

        // Keep the pattern where it would have been had the clipped-off start been walked.
        double skipped = Math.Sqrt((x0 - ox0) * (x0 - ox0) + (y0 - oy0) * (y0 - oy0));
        double p = ((phase + skipped) % period + period) % period;
        double length = Math.Sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0));
        double ux = length > 0 ? (x1 - x0) / length : 0, uy = length > 0 ? (y1 - y0) / length : 0;
        double pos = 0;
        while (pos < length)
        {
            // A step below the resolution of pos would not move it: then the pattern moves on instead, so the
            // walk always ends (a long segment with p a hair below a boundary used to loop for ever).
            if (p < dashOn)
            {
                double end = Math.Min(length, pos + (dashOn - p));
                if (end > pos) DrawLine(x0 + ux * pos, y0 + uy * pos, x0 + ux * end, y0 + uy * end, colour, thickness);
                p = end > pos ? p + (end - pos) : dashOn;
                pos = end;
            }
            else
            {
                double end = Math.Min(length, pos + (period - p));
                p = end > pos ? p + (end - pos) : period;
                pos = end;
            }

            if (p >= period) p -= period;
        }

        phase = ((phase + fullLength) % period + period) % period;
    }

    /// <summary>An anti-aliased filled disc.</summary>
    public void FillCircle(double cx, double cy, double radius, Rgb colour)
    {
        if (!double.IsFinite(cx) || !double.IsFinite(cy) || !(radius > 0)) return;
        int colFrom = (int)Math.Max(_clipLeft, Math.Floor(cx - radius - 1));
        int colTo = (int)Math.Min(_clipRight - 1, Math.Ceiling(cx + radius + 1));
        int rowFrom = (int)Math.Max(_clipTop, Math.Floor(cy - radius - 1));
        int rowTo = (int)Math.Min(_clipBottom - 1, Math.Ceiling(cy + radius + 1));
        for (int row = rowFrom; row <= rowTo; row++)
        {
            for (int col = colFrom; col <= colTo; col++)
            {
                double ddx = col + 0.5 - cx, ddy = row + 0.5 - cy;
                double coverage = radius + 0.5 - Math.Sqrt(ddx * ddx + ddy * ddy);
                BlendPixel(col, row, colour, Math.Min(1, coverage));
            }
        }
    }

    /// <summary>Encodes the raster as a PNG file's bytes.</summary>
    public byte[] ToPng() => PngWriter.Encode(Width, Height, _rgb);

    private void CoverSegmentPixel(int col, int row, double x0, double y0, double dx, double dy, double lengthSquared,
        double half, Rgb colour)
    {
        double px = col + 0.5 - x0, py = row + 0.5 - y0;
        double t = Math.Clamp((px * dx + py * dy) / lengthSquared, 0, 1);
        double ex = px - t * dx, ey = py - t * dy;
        double coverage = half + 0.5 - Math.Sqrt(ex * ex + ey * ey);
        BlendPixel(col, row, colour, Math.Min(1, coverage));
    }

    /// <summary>Liang–Barsky: trims the segment to the box; false if nothing is left or a coordinate is not finite.</summary>
    internal static bool ClipSegment(ref double x0, ref double y0, ref double x1, ref double y1,
        double left, double top, double right, double bottom)
    {
        if (!double.IsFinite(x0) || !double.IsFinite(y0) || !double.IsFinite(x1) || !double.IsFinite(y1)) return false;
        double dx = x1 - x0, dy = y1 - y0;
        if (!double.IsFinite(dx) || !double.IsFinite(dy)) return false;
        double tEnter = 0, tLeave = 1;
        if (!Clip(-dx, x0 - left, ref tEnter, ref tLeave)) return false;
        if (!Clip(dx, right - x0, ref tEnter, ref tLeave)) return false;
        if (!Clip(-dy, y0 - top, ref tEnter, ref tLeave)) return false;
        if (!Clip(dy, bottom - y0, ref tEnter, ref tLeave)) return false;
        double sx = x0, sy = y0;
        x0 = sx + tEnter * dx;
        y0 = sy + tEnter * dy;
        x1 = sx + tLeave * dx;
        y1 = sy + tLeave * dy;
        return true;

        static bool Clip(double p, double q, ref double tEnter, ref double tLeave)
        {
            if (p == 0) return q >= 0;
            double r = q / p;
            if (p < 0)
            {
                if (r > tLeave) return false;
                if (r > tEnter) tEnter = r;
            }
            else
            {
                if (r < tEnter) return false;
                if (r < tLeave) tLeave = r;
            }

            return true;
        }
    }
}
