namespace Kosmos.PseudoHaptic
{
    /// <summary>Which way a <see cref="FieldTransfer"/> copies: from a component's serialized fields into an engine-free settings object, or back.</summary>
    public enum TransferDirection
    {
        FieldsToSettings,
        SettingsToFields,
    }

    /// <summary>
    /// Copies between a component's serialized fields (floats, as the inspector keeps them) and an engine-free settings
    /// object (doubles), either way, so that a component lists each of its fields once for both directions (its
    /// <c>Settings</c> property and its <c>Use(settings)</c> are the same list run one way or the other) and a field
    /// added to one direction cannot be missing from the other. Arrays are copied, never shared; a null array is
    /// empty on the other side.
    /// </summary>
    public static class FieldTransfer
    {
        /// <summary>A value of the same type on both sides (an int, an enum, a string).</summary>
        public static void Copy<T>(TransferDirection direction, ref T setting, ref T field)
        {
            if (direction == TransferDirection.FieldsToSettings) setting = field;
            else field = setting;
        }

        /// <summary>A double setting kept as a float field (rounded to the nearest float on the way in).</summary>
        public static void Copy(TransferDirection direction, ref double setting, ref float field)
        {
            if (direction == TransferDirection.FieldsToSettings) setting = field;
            else field = (float)setting;
        }

        /// <summary>A double array setting kept as a float array field (each rounded to the nearest float on the way in).</summary>
        public static void Copy(TransferDirection direction, ref double[] setting, ref float[] field)
        {
            if (direction == TransferDirection.FieldsToSettings) setting = ToDoubles(field);
            else field = ToFloats(setting);
        }

        /// <summary>Floats as doubles, in a new array (null gives an empty one).</summary>
        public static double[] ToDoubles(float[] values)
        {
            if (values == null) return new double[0];
            var result = new double[values.Length];
            for (int i = 0; i < result.Length; i++) result[i] = values[i];
            return result;
        }

        /// <summary>Doubles as the nearest floats, in a new array (null gives an empty one).</summary>
        public static float[] ToFloats(double[] values)
        {
            if (values == null) return new float[0];
            var result = new float[values.Length];
            for (int i = 0; i < result.Length; i++) result[i] = (float)values[i];
            return result;
        }
    }
}
