using System.Globalization;

namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>An opaque colour, 8 bits per channel (sRGB, as stored in the PNG).</summary>
public readonly record struct Rgb(byte R, byte G, byte B)
{
    public static Rgb White => new(255, 255, 255);
    public static Rgb Black => new(0, 0, 0);

    /// <summary>Parses "#rrggbb" or "rrggbb".</summary>
    public static Rgb FromHex(string hex)
    {
        ArgumentNullException.ThrowIfNull(hex);
        string s = hex.StartsWith('#') ? hex[1..] : hex;
        if (s.Length != 6 || !int.TryParse(s, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out int v))
        {
            throw new FormatException($"Not a colour of the form #rrggbb: '{hex}'.");
        }

        return new Rgb((byte)(v >> 16), (byte)(v >> 8), (byte)v);
    }

    /// <summary>This colour with <paramref name="over"/> painted on top at opacity <paramref name="alpha"/> (0..1).</summary>
    public Rgb Blend(Rgb over, double alpha)
    {
        if (!(alpha > 0)) return this;
        if (alpha >= 1) return over;
        return new Rgb(Mix(R, over.R, alpha), Mix(G, over.G, alpha), Mix(B, over.B, alpha));
    }

    public override string ToString() => $"#{R:x2}{G:x2}{B:x2}";

    private static byte Mix(byte under, byte over, double alpha) =>
        (byte)Math.Clamp((int)Math.Round(under + (over - under) * alpha), 0, 255);
}
