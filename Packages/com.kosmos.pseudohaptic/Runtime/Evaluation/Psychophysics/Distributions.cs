using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The standard normal distribution to full double precision in both tails: Φ(−z) = ½·Q(½, z²/2) with Q
    /// the regularized upper incomplete gamma function (Abramowitz and Stegun 26.2.30 / 6.5.17), computed by
    /// its series or continued fraction (Numerical Recipes §6.2); the quantile by bisection to a bracket, then
    /// Newton steps on that CDF. No dependencies.
    /// </summary>
    public static class Normal
    {
        const double InvSqrt2Pi = 0.39894228040143267794;

        /// <summary>φ(z), the density.</summary>
        public static double Pdf(double z) => InvSqrt2Pi * Math.Exp(-0.5 * z * z);

        /// <summary>Φ(z) = P(Z ≤ z); relative accuracy ~1e-15 in the lower tail.</summary>
        public static double Cdf(double z)
        {
            double lower, upper;
            Both(z, out lower, out upper);
            return lower;
        }

        /// <summary>P(Z &gt; z) = 1 − Φ(z); relative accuracy ~1e-15 in the upper tail.</summary>
        public static double UpperTail(double z)
        {
            double lower, upper;
            Both(z, out lower, out upper);
            return upper;
        }

        /// <summary>Φ(z) through Q(½, z²/2), the slower second method the tests hold the first against.</summary>
        public static double CdfByGamma(double z)
        {
            if (double.IsNaN(z)) return double.NaN;
            double tail = double.IsInfinity(z) ? 0 : 0.5 * Gamma.RegularizedQ(0.5, 0.5 * z * z);
            return z >= 0 ? 1 - tail : tail;
        }

        // W. J. Cody's rational Chebyshev approximations (ACM TOMS 19:22-32, 1993, algorithm 715 ANORM):
        // |z| ≤ 0.67449, |z| ≤ √32, and an asymptotic form beyond, each to about 1e-16 relative.
        static readonly double[] A = { 2.2352520354606839287, 161.02823106855587881, 1067.6894854603709582, 18154.981253343561249, 0.065682337918207449113 };
        static readonly double[] B = { 47.20258190468824187, 976.09855173777669322, 10260.932208618978205, 45507.789335026729956 };
        static readonly double[] C = { 0.39894151208813466764, 8.8831497943883759412, 93.506656132177855979, 597.27027639480026226, 2494.5375852903726711, 6848.1904505362823326, 11602.651437647350124, 9842.7148383839780218, 1.0765576773720192317e-8 };
        static readonly double[] D = { 22.266688044328115691, 235.38790178262499861, 1519.377599407554805, 6485.558298266760755, 18615.571640885098091, 34900.952721145977266, 38912.003286093271411, 19685.429676859990727 };
        static readonly double[] P = { 0.21589853405795699, 0.1274011611602473639, 0.022235277870649807, 0.001421619193227893466, 2.9112874951168792e-5, 0.02307344176494017303 };
        static readonly double[] Q = { 1.28426009614491121, 0.468238212480865118, 0.0659881378689285515, 0.00378239633202758244, 7.29751555083966205e-5 };

        /// <summary>Φ(z) and 1 − Φ(z), each accurate relative to itself.</summary>
        public static void Both(double z, out double lower, out double upper)
        {
            if (double.IsNaN(z)) { lower = upper = double.NaN; return; }
            double y = Math.Abs(z);
            if (y <= 0.67448975)
            {
                double num = 0, den = 0;
                if (y > 1.1e-16)
                {
                    double sq = z * z;
                    num = A[4] * sq;
                    den = sq;
                    for (int i = 0; i < 3; i++)
                    {
                        num = (num + A[i]) * sq;
                        den = (den + B[i]) * sq;
                    }
                }
                double t = z * (num + A[3]) / (den + B[3]);
                lower = 0.5 + t;
                upper = 0.5 - t;
                return;
            }
            double small; // the tail beyond y
            if (y <= 5.656854249492380195)
            {
                double num = C[8] * y, den = y;
                for (int i = 0; i < 7; i++)
                {
                    num = (num + C[i]) * y;
                    den = (den + D[i]) * y;
                }
                small = Scaled(y, (num + C[7]) / (den + D[7]));
            }
            else if (y < 40)
            {
                double sq = 1 / (y * y);
                double num = P[5] * sq, den = sq;
                for (int i = 0; i < 4; i++)
                {
                    num = (num + P[i]) * sq;
                    den = (den + Q[i]) * sq;
                }
                double t = sq * (num + P[4]) / (den + Q[4]);
                small = Scaled(y, (InvSqrt2Pi - t) / y);
            }
            else small = 0;
            if (z > 0) { upper = small; lower = 1 - small; }
            else { lower = small; upper = 1 - small; }
        }

        /// <summary>exp(−y²/2)·r, with y² split so that its rounding does not spoil the exponential.</summary>
        static double Scaled(double y, double r)
        {
            double head = Math.Floor(y * 16) / 16;
            double del = (y - head) * (y + head);
            return Math.Exp(-head * head * 0.5) * Math.Exp(-del * 0.5) * r;
        }

        /// <summary>Φ⁻¹(p), 0 &lt; p &lt; 1. Quantile(0.975) = 1.959963984540054, Quantile(0.75) = 0.6744897501960817.</summary>
        public static double Quantile(double p)
        {
            if (!(p > 0 && p < 1)) throw new ArgumentOutOfRangeException(nameof(p), p, "probability must be in (0, 1)");
            if (p == 0.5) return 0;
            if (p > 0.5) return -LowerQuantile(1 - p);
            return LowerQuantile(p);
        }

        /// <summary>The z &lt; 0 with Φ(z) = p &lt; ½.</summary>
        static double LowerQuantile(double p)
        {
            double lo = -40, hi = 0;
            for (int i = 0; i < 60; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (UpperTail(-mid) > p) hi = mid; else lo = mid;
            }
            double z = 0.5 * (lo + hi);
            for (int i = 0; i < 8; i++)
            {
                // Newton on ln Φ: the step is relative in the tail, so it stays accurate where p is tiny.
                double f = UpperTail(-z);
                double step = (f - p) / Pdf(z);
                if (!(Math.Abs(step) > 0) || double.IsInfinity(step)) break;
                z -= step;
                if (Math.Abs(step) < 1e-16 * (1 + Math.Abs(z))) break;
            }
            return z;
        }
    }

    /// <summary>
    /// The chi-square distribution's upper tail, P(X &gt; x) = Q(ν/2, x/2), for 0 &lt; ν ≤ 10⁶ (Friedman's test asks ν = k − 1):
    /// ln Γ(ν/2) cancels as ν grows (5e-10 of the tail at ν = 10⁶, DistributionsContractTests) and from ν ≈ 3·10⁸ the series
    /// needs more than its 100,000 terms.
    /// </summary>
    public static class ChiSquare
    {
        public static double UpperTail(double x, double degreesOfFreedom)
        {
            if (!(degreesOfFreedom > 0 && degreesOfFreedom <= 1e6)) throw new ArgumentOutOfRangeException(nameof(degreesOfFreedom), degreesOfFreedom, "degrees of freedom must be positive and at most a million");
            if (double.IsNaN(x)) return double.NaN;
            if (x <= 0) return 1;
            return Gamma.RegularizedQ(0.5 * degreesOfFreedom, 0.5 * x);
        }
    }

    /// <summary>The regularized upper incomplete gamma function Q(a, x) = 1 − P(a, x) (Numerical Recipes §6.2).</summary>
    static class Gamma
    {
        /// <summary>Q(a, x), the upper one, accurate relative to itself where it is small.</summary>
        public static double RegularizedQ(double a, double x)
        {
            if (x <= 0) return 1;
            if (double.IsPositiveInfinity(x)) return 0;
            if (x < a + 1) return 1 - Series(a, x);
            return ContinuedFraction(a, x);
        }

        static double Series(double a, double x)
        {
            double ap = a, term = 1 / a, sum = term;
            for (int n = 0; n < 100000; n++)
            {
                ap += 1;
                term *= x / ap;
                sum += term;
                if (Math.Abs(term) < Math.Abs(sum) * 1e-17) break;
            }
            return sum * Math.Exp(-x + a * Math.Log(x) - StudentT.LogGamma(a));
        }

        static double ContinuedFraction(double a, double x)
        {
            const double tiny = 1e-300;
            double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
            for (int i = 1; i < 100000; i++)
            {
                double an = -i * (i - a);
                b += 2;
                d = an * d + b; if (Math.Abs(d) < tiny) d = tiny;
                c = b + an / c; if (Math.Abs(c) < tiny) c = tiny;
                d = 1 / d;
                double del = d * c;
                h *= del;
                if (Math.Abs(del - 1) < 1e-16) break;
            }
            return Math.Exp(-x + a * Math.Log(x) - StudentT.LogGamma(a)) * h;
        }
    }
}
