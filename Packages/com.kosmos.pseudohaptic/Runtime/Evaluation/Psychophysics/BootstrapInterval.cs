namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>How <see cref="PsychometricBootstrap"/> turns its refitted values into an interval.</summary>
    public enum BootstrapInterval
    {
        /// <summary>Bias-corrected and accelerated (Efron 1987; Efron and Tibshirani 1993, §14.3), as Wichmann and Hill
        /// (2001b) recommend for psychometric functions: the percentiles are moved by the share of refitted values below the
        /// fit (the bias, z₀) and by the skew of the trial-by-trial jackknife (the acceleration, a). With few trials the
        /// maximum-likelihood JND comes out too small and a plain percentile interval carries that bias; this one corrects
        /// most of it (evaluation.md §8.3). The default.</summary>
        Bca = 0,

        /// <summary>The 2.5 and 97.5 percentiles of the refitted values (at 95 %), the package's only interval up to version
        /// 0.4.0: for reproducing an analysis made with it.</summary>
        Percentile = 1,
    }
}
