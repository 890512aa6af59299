namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>Which inside corner of the plot area holds a chart's legend.</summary>
public enum LegendPosition
{
    /// <summary>The corner whose legend box covers the fewest data points and line segments; top left on a tie.</summary>
    Best,
    TopLeft,
    TopRight,
    BottomLeft,
    BottomRight,
}
