namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>
/// Where a chart's plot area lies in the image and which data ranges it shows: maps data to pixel coordinates
/// (continuous; x grows rightwards, y upwards in data and downwards in pixels).
/// </summary>
internal readonly record struct PlotFrame(
    int Left,
    int Top,
    int Width,
    int Height,
    double XMin,
    double XMax,
    double YMin,
    double YMax,
    bool LogX)
{
    public int Right => Left + Width;

    public int Bottom => Top + Height;

    /// <summary>Pixel x of data x; NaN where the axis cannot show it (e.g. x ≤ 0 on a log axis).</summary>
    public double MapX(double x)
    {
        if (LogX)
        {
            if (!(x > 0)) return double.NaN;
            double lo = Math.Log10(XMin), hi = Math.Log10(XMax);
            return Left + (Math.Log10(x) - lo) / (hi - lo) * Width;
        }

        return Left + (x - XMin) / (XMax - XMin) * Width;
    }

    /// <summary>Pixel y of data y.</summary>
    public double MapY(double y) => Bottom - (y - YMin) / (YMax - YMin) * Height;
}
