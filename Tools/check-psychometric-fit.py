#!/usr/bin/env python3
"""Reference maxima for PsychometricFitMaximumTests (Tests/Editor/Evaluation): the maximum-likelihood cumulative
Gaussian Ψ(x) = γ + (1 − 2γ)·Φ((x − μ)/σ), γ fixed, of thirteen data sets, found in 50-digit arithmetic (mpmath) by a
coarse grid over (μ, ln σ), wider than the levels, for the global maximum and Newton's method on the exact gradient to
polish its three likeliest points; prints μ, σ, the log-likelihood and the deviance to 17 significant digits, the
figures the tests hold the fit to. For a set whose answers fall it prints the falling curve's maximum,
Ψ(x) = γ + (1 − 2γ)·Φ(−(x − μ)/σ), too or instead (a few minutes).

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
    # Twenty trials at eight levels, 13 of 20 heavier at the lightest, few in the middle, more again at the heaviest:
    # under a lapse of 0.2 a rising curve has a maximum (the ascent from (0, 1) ends there) but a falling one is likelier.
    "falling, lapse 0.2": (LEVELS[:8], [20] * 8, [13, 3, 4, 3, 4, 7, 10, 8], 0.2, [1, -1]),
    # Five trials at four levels, 4, 5, 3 and 4 heavier, under a lapse of 0.1: a shallow fall, likelier than any rise
    # (none has a maximum: the likeliest is flat, Ψ = 0.8 everywhere, −10.008) or step, which only a start that falls finds.
    "shallow fall, lapse 0.1": (LEVELS[:4], [5] * 4, [4, 5, 3, 4], 0.1, [-1]),
    # Four data sets on which a single grid start was not enough (seeds 4950, 6831, 2169 and 823 of the search in
    # PsychometricFitStartsTests, evaluation.md 8.3, moved onto these levels): the likeliest point of the grid lay on the
    # flank of a hill lower than the highest one.
    # Six trials at eight levels, nearly all heavier, under a lapse of 0.04: a shallow curve centred far below the levels.
    "shallow, far below, lapse 0.04": (LEVELS[:8], [6] * 8, [5, 4, 6, 6, 6, 5, 5, 5], 0.04),
    # Twenty trials at six levels, 1 of 20 heavier at the lightest, then 14: a steep rise between the first two levels.
    "a steep rise, lapse 0.01": (LEVELS[:6], [20] * 6, [1, 14, 19, 17, 19, 20], 0.01),
    # Eighteen trials at nine levels, a jump between the fourth and the fifth: steep, but a curve, not a step.
    "a jump, lapse 0.02": (LEVELS, [18] * 9, [2, 2, 2, 1, 15, 16, 17, 16, 18], 0.02),
    # Nine trials at eight levels, few heavier anywhere, under a lapse of 0.1: a shallow rise is likelier than any fall.
    "few heavier, lapse 0.1": (LEVELS[:8], [9] * 8, [2, 0, 2, 0, 2, 3, 2, 1], 0.1, [1, -1]),
}


def psi(x, mu, s, g, direction=1):
    return g + (1 - 2 * g) * mp.ncdf(direction * (x - mu) / s)


def loglik(data, mu, s, direction=1):
    xs, ns, ks, g = data[:4]
    total = mp.mpf(0)
    for x, n, k in zip(xs, ns, ks):
        x = mp.mpf(x)
        p = psi(x, mu, s, g, direction)
        if k > 0:
            total += k * mp.log(p)
        if n - k > 0:
            total += (n - k) * mp.log(1 - p)
    return total


def deviance(data, mu, s, direction=1):
    xs, ns, ks, g = data[:4]
    d = mp.mpf(0)
    for x, n, k in zip(xs, ns, ks):
        p = psi(mp.mpf(x), mu, s, g, direction)
        if k > 0:
            d += k * mp.log(k / (n * p))
        if n - k > 0:
            d += (n - k) * mp.log((n - k) / (n * (1 - p)))
    return 2 * d


def polish(data, mu, s, direction):
    """Newton on the gradient in (μ, ln σ) from (mu, s); None if it runs off (σ beyond 1e6) or onto a flat place."""
    f = lambda m, t: loglik(data, m, mp.exp(t), direction)
    m, t = mp.mpf(mu), mp.log(s)
    for _ in range(100):
        g = [mp.diff(f, (m, t), (1, 0)), mp.diff(f, (m, t), (0, 1))]
        h = [[mp.diff(f, (m, t), (2, 0)), mp.diff(f, (m, t), (1, 1))],
             [mp.diff(f, (m, t), (1, 1)), mp.diff(f, (m, t), (0, 2))]]
        try:
            step = mp.lu_solve(mp.matrix(h), mp.matrix(g))
        except ZeroDivisionError:  # a flat place (σ so large or small that the likelihood does not move)
            return None
        m, t = m - step[0], t - step[1]
        if t > mp.log(1e6):
            return None
        if abs(step[0]) + abs(step[1]) < mp.mpf(10) ** -40:
            break
    return m, mp.exp(t)


def maximum(data, direction=1):
    xs = data[0]
    lo, hi = min(xs), max(xs)
    grid = []
    # μ from four spreads below the levels to four above them, σ from 0.005 to 2.
    for i in range(361):
        mu = mp.mpf(lo) + (mp.mpf(hi) - lo) * (i - 160) / 40
        for j in range(41):
            s = mp.exp(mp.log(0.005) + (mp.log(2.0) - mp.log(0.005)) * j / 40)
            grid.append((loglik(data, mu, s, direction), mu, s))
    grid.sort(key=lambda c: c[0], reverse=True)
    # The three likeliest points of the grid polished; the likeliest maximum they reach.
    found = [polish(data, mu, s, direction) for _, mu, s in grid[:3]]
    return max((p for p in found if p is not None), key=lambda p: loglik(data, p[0], p[1], direction))


for name, data in SETS.items():
    for direction in (data[4] if len(data) > 4 else [1]):
        mu, s = maximum(data, direction)
        print("%-32s mu %s  sigma %s  loglik %s  deviance %s" % (
            name + (", falling curve" if direction < 0 else ""), mp.nstr(mu, 17), mp.nstr(s, 17),
            mp.nstr(loglik(data, mu, s, direction), 17), mp.nstr(deviance(data, mu, s, direction), 17)))
