namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>A small qualitative palette (the "tab10" colours) for telling series apart.</summary>
public static class Palette
{
    private static readonly Rgb[] Colours =
    {
        new(0x1f, 0x77, 0xb4), // blue
        new(0xff, 0x7f, 0x0e), // orange
        new(0x2c, 0xa0, 0x2c), // green
        new(0xd6, 0x27, 0x28), // red
        new(0x94, 0x67, 0xbd), // purple
        new(0x8c, 0x56, 0x4b), // brown
        new(0xe3, 0x77, 0xc2), // pink
        new(0x7f, 0x7f, 0x7f), // grey
        new(0xbc, 0xbd, 0x22), // olive
        new(0x17, 0xbe, 0xcf), // cyan
    };

    /// <summary>Number of distinct colours before <see cref="Get"/> repeats.</summary>
    public static int Count => Colours.Length;

    /// <summary>The i-th palette colour; wraps around (any int, negative too, is valid).</summary>
    public static Rgb Get(int i) => Colours[((i % Colours.Length) + Colours.Length) % Colours.Length];
}
