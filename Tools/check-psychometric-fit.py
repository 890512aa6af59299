#!/usr/bin/env python3
"""Reference maxima for PsychometricFitMaximumTests (Tests/Editor/Evaluation): the maximum-likelihood cumulative
Gaussian Ψ(x) = γ + (1 − 2γ)·Φ((x − μ)/σ), γ fixed, of seven data sets, found in 50-digit arithmetic (mpmath) by a
coarse grid over (μ, ln σ) for the global maximum and Newton's method on the exact gradient to polish it; prints μ, σ,
the log-likelihood and the deviance to 17 significant digits, the figures the tests hold the fit to.

Usage: python3 Tools/check-psychometric-fit.py"""
import mpmath as mp

mp.mp.dps = 50

LEVELS = [0.80, 0.85, 0.90, 0.95, 1.00, 1.05, 1.10, 1.15, 1.20]
SETS = {
    # name: (levels, trials, heavier, lapse)
    "graded": (LEVELS, [10] * 9, [0, 1, 1, 3, 5, 6, 8, 10, 9], 0),
    "graded, lapse 0.04": (LEVELS, [10] * 9, [0, 1, 1, 3, 5, 6, 8, 10, 9], 0.04),
    "lapsing, lapse 0.2": (LEVELS, [10] * 9, [3, 2, 1, 3, 6, 6, 8, 9, 7], 0.2),
    "graded, a thousand times": (LEVELS, [10000] * 9, [0, 1000, 1000, 3000, 5000, 6000, 8000, 10000, 9000], 0),
    # A participant who lapsed at the heaviest comparison (1 of 10): the ascent from the lapse-free maximum stops at a
    # lesser maximum (μ 0.98, σ 0.16, log-likelihood −55.3); the fit's other start finds this one.
    "an outlier, lapse 0.1": (LEVELS, [10] * 9, [0, 0, 2, 7, 10, 7, 10, 8, 1], 0.1),
    # Forty trials a level, the eighth level answered heavier 8 times in 40 against its neighbours' 40 and 38: under a
    # lapse of 0.02 the likeliest curve is steep (σ 0.035) and that outlier improbable; the ascents from (0, 1) and from
    # the lapse-free maximum both end at a shallow one (σ 0.24, log-likelihood −198.6), the grid start finds this one.
    "an outlier of forty, lapse 0.02": (LEVELS, [40] * 9, [0, 14, 30, 39, 40, 40, 40, 8, 38], 0.02),
    # A simulated observer's 700 trials (SimulatedObserver(1.02, 0.09, seed 81), ConstantStimuliPlan, 100 repetitions):
    # its ascent ends with a gradient of about 1.7e-6, at the maximum to rounding.
    "seven levels of a hundred": ([0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3], [100] * 7, [0, 1, 11, 43, 83, 98, 100], 0),
}


def psi(x, mu, s, g):
    return g + (1 - 2 * g) * mp.ncdf((x - mu) / s)


def loglik(data, mu, s):
    xs, ns, ks, g = data
    total = mp.mpf(0)
    for x, n, k in zip(xs, ns, ks):
        x = mp.mpf(x)
        p = psi(x, mu, s, g)
        if k > 0:
            total += k * mp.log(p)
        if n - k > 0:
            total += (n - k) * mp.log(1 - p)
    return total


def deviance(data, mu, s):
    xs, ns, ks, g = data
    d = mp.mpf(0)
    for x, n, k in zip(xs, ns, ks):
        p = psi(mp.mpf(x), mu, s, g)
        if k > 0:
            d += k * mp.log(k / (n * p))
        if n - k > 0:
            d += (n - k) * mp.log((n - k) / (n * (1 - p)))
    return 2 * d


def maximum(data):
    xs = data[0]
    lo, hi = min(xs), max(xs)
    best = None
    for i in range(41):
        mu = mp.mpf(lo) + (mp.mpf(hi) - lo) * i / 40
        for j in range(41):
            s = mp.exp(mp.log(0.005) + (mp.log(1.0) - mp.log(0.005)) * j / 40)
            v = loglik(data, mu, s)
            if best is None or v > best[0]:
                best = (v, mu, s)
    _, mu, s = best
    # Newton on the gradient in (μ, ln σ).
    f = lambda m, t: loglik(data, m, mp.exp(t))
    m, t = mp.mpf(mu), mp.log(s)
    for _ in range(100):
        g = [mp.diff(f, (m, t), (1, 0)), mp.diff(f, (m, t), (0, 1))]
        h = [[mp.diff(f, (m, t), (2, 0)), mp.diff(f, (m, t), (1, 1))],
             [mp.diff(f, (m, t), (1, 1)), mp.diff(f, (m, t), (0, 2))]]
        step = mp.lu_solve(mp.matrix(h), mp.matrix(g))
        m, t = m - step[0], t - step[1]
        if abs(step[0]) + abs(step[1]) < mp.mpf(10) ** -40:
            break
    return m, mp.exp(t)


for name, data in SETS.items():
    mu, s = maximum(data)
    print("%-32s mu %s  sigma %s  loglik %s  deviance %s" % (
        name, mp.nstr(mu, 17), mp.nstr(s, 17), mp.nstr(loglik(data, mu, s), 17), mp.nstr(deviance(data, mu, s), 17)))
