using System;
using System.Globalization;

namespace Kosmos.PseudoHaptic
{
    /// <summary>What kind of value a setting holds.</summary>
    public enum SettingKind
    {
        /// <summary>A real number in [<see cref="SettingDescriptor.Min"/>, <see cref="SettingDescriptor.Max"/>].</summary>
        Number = 0,
        /// <summary>On or off (1 or 0 in an <see cref="EffectSettings"/>; true/false in a profile file).</summary>
        Boolean = 1,
    }

    /// <summary>
    /// One setting of an effect (or of the safety limits), declared once beside the effect: its name (as in profile files,
    /// the Unity list and the docs; the constructor parameter's name), unit, default, valid range and a one-line summary.
    /// The effect's constructor validates through <see cref="Check"/>, so the range written here is the range enforced.
    /// Immutable.
    /// </summary>
    public sealed class SettingDescriptor
    {
        public string Name { get; }
        /// <summary>The unit as written in docs ("m", "s", "m/s", "" for a ratio).</summary>
        public string Unit { get; }
        public string Summary { get; }
        public SettingKind Kind { get; }
        public double Default { get; }
        public double Min { get; }
        public double Max { get; }
        /// <summary>True when <see cref="Min"/> itself is not allowed (a value must be greater than it).</summary>
        public bool MinExclusive { get; }

        readonly Func<object, double> _read;

        SettingDescriptor(string name, string unit, SettingKind kind, double @default, double min, double max, bool minExclusive, string summary, Func<object, double> read)
        {
            if (string.IsNullOrWhiteSpace(name)) throw new ArgumentException("a setting needs a name.", nameof(name));
            Name = name;
            Unit = unit ?? "";
            Kind = kind;
            Min = min;
            Max = max;
            MinExclusive = minExclusive;
            Summary = summary ?? "";
            _read = read;
            Default = Check(@default);
        }

        /// <summary>A finite number in [min, max] (either bound may be infinite: the range is then unbounded on that side).</summary>
        public static SettingDescriptor Number<T>(string name, string unit, double @default, double min, double max, string summary, Func<T, double> read)
            => new SettingDescriptor(name, unit, SettingKind.Number, @default, min, max, false, summary, Reader(read));

        /// <summary>A finite number greater than 0 (and at most <paramref name="max"/>).</summary>
        public static SettingDescriptor Positive<T>(string name, string unit, double @default, string summary, Func<T, double> read, double max = double.PositiveInfinity)
            => new SettingDescriptor(name, unit, SettingKind.Number, @default, 0, max, true, summary, Reader(read));

        public static SettingDescriptor Boolean<T>(string name, bool @default, string summary, Func<T, bool> read)
        {
            if (read == null) throw new ArgumentNullException(nameof(read));
            return new SettingDescriptor(name, "", SettingKind.Boolean, @default ? 1 : 0, 0, 1, false, summary, o => read((T)o) ? 1 : 0);
        }

        static Func<object, double> Reader<T>(Func<T, double> read)
        {
            if (read == null) throw new ArgumentNullException(nameof(read));
            return o => read((T)o);
        }

        /// <summary>The value <paramref name="owner"/> (an effect of this setting's type, or limits) holds.</summary>
        public double Read(object owner) => _read(owner);

        /// <summary>The value when it is valid; throws <see cref="ArgumentOutOfRangeException"/> naming the setting otherwise.</summary>
        public double Check(double value)
        {
            if (Kind == SettingKind.Boolean)
            {
                if (value == 0 || value == 1) return value;
                throw new ArgumentOutOfRangeException(Name, value, Name + " must be true or false (1 or 0), got " + Text(value) + ".");
            }
            // Only Positive makes MinExclusive, with Min = 0.
            if (MinExclusive && double.IsPositiveInfinity(Max)) return ConfigurationGuard.Positive(value, Name);
            // An infinite bound leaves that side open; the value itself is still finite.
            if (double.IsNegativeInfinity(Min) || double.IsPositiveInfinity(Max)) ConfigurationGuard.Finite(value, Name);
            if (MinExclusive)
            {
                if (double.IsNaN(value) || value <= Min || value > Max) // Max is finite here, so ±∞ fails a bound
                    throw new ArgumentOutOfRangeException(Name, value, Name + " must lie in (" + Text(Min) + ", " + Text(Max) + "], got " + Text(value) + ".");
                return value;
            }
            return ConfigurationGuard.InRange(value, Min, Max, Name);
        }

        /// <summary>The valid range as docs write it: "[0.001, 10]", "> 0", "(0, 2]", ">= 1", "<= 1", "any finite", "true/false".</summary>
        public string RangeText
        {
            get
            {
                if (Kind == SettingKind.Boolean) return "true/false";
                if (MinExclusive && double.IsPositiveInfinity(Max)) return "> " + Text(Min);
                if (MinExclusive) return "(" + Text(Min) + ", " + Text(Max) + "]";
                if (double.IsNegativeInfinity(Min)) return double.IsPositiveInfinity(Max) ? "any finite" : "<= " + Text(Max);
                if (double.IsPositiveInfinity(Max)) return ">= " + Text(Min);
                return "[" + Text(Min) + ", " + Text(Max) + "]";
            }
        }

        /// <summary>A value as profile files and docs write it (round-trip: read back, it is the same double).</summary>
        public string Format(double value) => Kind == SettingKind.Boolean ? (value != 0 ? "true" : "false") : Text(value);

        internal static string Text(double value) => value.ToString("R", CultureInfo.InvariantCulture);

        public override string ToString() => Name;
    }
}
