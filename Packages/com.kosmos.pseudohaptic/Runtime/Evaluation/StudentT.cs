using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Student's t distribution, for confidence intervals of a mean: the CDF from the regularized
    /// incomplete beta function, P(T > t) = ½·I_{ν/(ν+t²)}(ν/2, ½) (Abramowitz and Stegun 26.7.1), by its
    /// continued fraction (Numerical Recipes §6.4); the quantile by bisection on that tail to full double
    /// precision. Above 1000 degrees of freedom, and for ν = ∞, the Cornish–Fisher expansion around the
    /// normal quantile (A&amp;S 26.7.5), accurate there to far below 1e-9; the CDF there inverts that
    /// expansion (the beta form cancels as ν grows). No dependencies.
    /// </summary>
    public static class StudentT
    {
        const double ExactUpTo = 1000;

        /// <summary>P(T ≤ t) for ν = <paramref name="degreesOfFreedom"/> &gt; 0.</summary>
        public static double Cdf(double t, double degreesOfFreedom)
        {
            CheckDf(degreesOfFreedom);
            if (double.IsNaN(t)) return double.NaN;
            if (double.IsPositiveInfinity(degreesOfFreedom)) return NormalCdfFromTail(t);
            // As ν grows the incomplete beta function cancels (1 − ν/(ν + t²), ln Γ(ν/2 + ½) − ln Γ(ν/2)): P(T ≤ 1) read
            // ½ at ν = 1e16 (StudentTEdgeTests). Past ExactUpTo invert the expansion the quantile uses, so that the two agree.
            if (degreesOfFreedom > ExactUpTo) return NormalCdfFromTail(InverseCornishFisher(t, degreesOfFreedom));
            double tail = UpperTail(Math.Abs(t), degreesOfFreedom);
            return t >= 0 ? 1 - tail : tail;
        }

        /// <summary>
        /// The t with P(T ≤ t) = <paramref name="p"/>, 0 &lt; p &lt; 1; ν may be
        /// <see cref="double.PositiveInfinity"/> (the normal quantile). Quantile(0.975, 11) = 2.2009852.
        /// </summary>
        public static double Quantile(double p, double degreesOfFreedom)
        {
            CheckDf(degreesOfFreedom);
            if (!(p > 0 && p < 1)) throw new ArgumentOutOfRangeException(nameof(p), p, "probability must be in (0, 1)");
            if (p == 0.5) return 0;
            double upper = p > 0.5 ? 1 - p : p; // the one-sided tail beyond |t|
            double magnitude = degreesOfFreedom > ExactUpTo ? CornishFisher(upper, degreesOfFreedom) : SolveTail(upper, degreesOfFreedom);
            return p > 0.5 ? magnitude : -magnitude;
        }

        /// <summary>The two-sided critical value for a confidence level (0.95 → t such that 2.5 % lies above it).</summary>
        public static double TwoSidedCritical(double confidence, double degreesOfFreedom)
        {
            if (!(confidence > 0 && confidence < 1)) throw new ArgumentOutOfRangeException(nameof(confidence), confidence, "confidence must be in (0, 1)");
            return Quantile(1 - (1 - confidence) / 2, degreesOfFreedom);
        }

        static void CheckDf(double df)
        {
            if (!(df > 0)) throw new ArgumentOutOfRangeException("degreesOfFreedom", df, "degrees of freedom must be positive");
        }

        /// <summary>P(T &gt; t), t ≥ 0.</summary>
        static double UpperTail(double t, double df)
        {
            if (double.IsPositiveInfinity(t)) return 0;
            double x = df / (df + t * t);
            return 0.5 * RegularizedIncompleteBeta(0.5 * df, 0.5, x);
        }

        static double SolveTail(double tail, double df)
        {
            // Bracket: the tail falls from ½ at 0; double hi until it is below the target.
            double lo = 0, hi = 1;
            while (UpperTail(hi, df) > tail)
            {
                lo = hi;
                hi *= 2;
                if (hi > 1e300) return double.PositiveInfinity;
            }
            for (int i = 0; i < 400; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break; // adjacent doubles: as close as it gets
                if (UpperTail(mid, df) > tail) lo = mid; else hi = mid;
            }
            return 0.5 * (lo + hi);
        }

        static double CornishFisher(double tail, double df)
        {
            double z = NormalUpperQuantile(tail);
            if (double.IsPositiveInfinity(df)) return z;
            return CornishFisherExpansion(z, df);
        }

        /// <summary>t of the normal quantile z (A&amp;S 26.7.5 to ν⁻⁴); increasing in z, and t ≥ z ≥ 0, for ν &gt; <see cref="ExactUpTo"/>.</summary>
        static double CornishFisherExpansion(double z, double df)
        {
            double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, z9 = z7 * z2;
            double g1 = (z3 + z) / 4;
            double g2 = (5 * z5 + 16 * z3 + 3 * z) / 96;
            double g3 = (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / 384;
            double g4 = (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / 92160;
            return z + g1 / df + g2 / (df * df) + g3 / (df * df * df) + g4 / (df * df * df * df);
        }

        /// <summary>The z whose <see cref="CornishFisherExpansion"/> is t: bisection on [0, |t|], odd in t.</summary>
        static double InverseCornishFisher(double t, double df)
        {
            double target = Math.Abs(t);
            if (double.IsPositiveInfinity(target)) return t;
            double lo = 0, hi = Math.Min(target, 40); // Φ(−40) is below the least double
            for (;;)
            {
                double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                if (CornishFisherExpansion(mid, df) < target) lo = mid; else hi = mid;
            }
            double z = 0.5 * (lo + hi);
            return t < 0 ? -z : z;
        }

        /// <summary>The z with P(Z &gt; z) = tail, 0 &lt; tail &lt; ½: bisection on the normal tail ½·erfc(z/√2).</summary>
        static double NormalUpperQuantile(double tail)
        {
            double lo = 0, hi = 40;
            for (int i = 0; i < 200; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                if (NormalUpperTail(mid) > tail) lo = mid; else hi = mid;
            }
            return 0.5 * (lo + hi);
        }

        static double NormalCdfFromTail(double z) => z >= 0 ? 1 - NormalUpperTail(z) : NormalUpperTail(-z);

        /// <summary>P(Z &gt; z) = ½·Q(½, z²/2) for z ≥ 0, Q the regularized upper incomplete gamma.</summary>
        static double NormalUpperTail(double z) => z <= 0 ? 0.5 : 0.5 * Gamma.RegularizedQ(0.5, 0.5 * z * z);

        /// <summary>I_x(a, b), the regularized incomplete beta function.</summary>
        internal static double RegularizedIncompleteBeta(double a, double b, double x)
        {
            if (x <= 0) return 0;
            if (x >= 1) return 1;
            double lnFront = LogGamma(a + b) - LogGamma(a) - LogGamma(b) + a * Math.Log(x) + b * Math.Log(1 - x);
            double front = Math.Exp(lnFront);
            if (x < (a + 1) / (a + b + 2)) return front * BetaContinuedFraction(a, b, x) / a;
            return 1 - front * BetaContinuedFraction(b, a, 1 - x) / b;
        }

        static double BetaContinuedFraction(double a, double b, double x)
        {
            const double tiny = 1e-300;
            double qab = a + b, qap = a + 1, qam = a - 1;
            double c = 1, d = 1 - qab * x / qap;
            if (Math.Abs(d) < tiny) d = tiny;
            d = 1 / d;
            double h = d;
            for (int m = 1; m <= 100000; m++)
            {
                int m2 = 2 * m;
                double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
                d = 1 + aa * d; if (Math.Abs(d) < tiny) d = tiny;
                c = 1 + aa / c; if (Math.Abs(c) < tiny) c = tiny;
                d = 1 / d;
                h *= d * c;
                aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
                d = 1 + aa * d; if (Math.Abs(d) < tiny) d = tiny;
                c = 1 + aa / c; if (Math.Abs(c) < tiny) c = tiny;
                d = 1 / d;
                double del = d * c;
                h *= del;
                if (Math.Abs(del - 1) < 1e-15) break;
            }
            return h;
        }

        static readonly double[] Lanczos =
        {
            0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313,
            -176.61502916214059, 12.507343278686905, -0.13857109526572012, 9.9843695780195716e-6,
            1.5056327351493116e-7,
        };

        /// <summary>ln Γ(x), x &gt; 0 (Lanczos, g = 7, n = 9; relative error about 1e-15).</summary>
        internal static double LogGamma(double x)
        {
            if (x < 0.5) return Math.Log(Math.PI / Math.Abs(Math.Sin(Math.PI * x))) - LogGamma(1 - x);
            x -= 1;
            double sum = Lanczos[0];
            double t = x + 7.5;
            for (int i = 1; i < Lanczos.Length; i++) sum += Lanczos[i] / (x + i);
            return 0.5 * Math.Log(2 * Math.PI) + (x + 0.5) * Math.Log(t) - t + Math.Log(sum);
        }
    }
}
