using ScottPlot;

namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>
/// A chart laid out and not yet drawn: one plot, or panels stacked top to bottom, at their size in pixels. A command
/// draws it as a PNG and, with <c>--svg</c>, builds it again and draws it as an SVG of the same size (a plot is laid
/// out when it is drawn, so each image gets a fresh one).
/// </summary>
public sealed class Figure
{
    readonly Plot[] _panels;
    readonly int _width;
    readonly int[] _heights;

    public Figure(Plot plot, int width, int height) : this(new[] { plot }, width, new[] { height }) { }

    public Figure(Plot[] panels, int width, int[] heights)
    {
        ArgumentNullException.ThrowIfNull(panels);
        ArgumentNullException.ThrowIfNull(heights);
        if (panels.Length == 0 || panels.Length != heights.Length) throw new ArgumentException("one height per panel, at least one panel");
        _panels = panels;
        _width = width;
        _heights = heights;
    }

    public byte[] Png() => _panels.Length == 1 ? Charts.Png(_panels[0], _width, _heights[0]) : Charts.PanelsPng(_panels, _width, _heights);

    public string Svg() => _panels.Length == 1 ? Charts.Svg(_panels[0], _width, _heights[0]) : Charts.PanelsSvg(_panels, _width, _heights);
}
