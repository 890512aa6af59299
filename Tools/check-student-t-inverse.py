#!/usr/bin/env python3
"""Checks two Stryker survivors of StudentT.InverseCornishFisher (Runtime/Evaluation/StudentT.cs) against the original,
in IEEE doubles with the same operations in the same order (Python's float is the same binary64 as C#'s double):

- bracket [0, Math.Max(|t|, 40)] instead of [0, Math.Min(|t|, 40)] (id 4177 at bc76b08): the same z wherever it
  matters (below 38; above, Φ's tail underflows to 0 either way);
- `CornishFisherExpansion(mid, df) <= target` instead of `<` (id 4189): how often and by how many ulps of z they differ.

Usage: python3 Tools/check-student-t-inverse.py [draws] (default 20000, seed 1). Figures in mutation-survivors.md,
"evaluation-questionnaire (93.62 %...)"."""
import math, random, sys


def expansion(z, df):
    # StudentT.CornishFisherExpansion, term for term.
    z2 = z * z; z3 = z2 * z; z5 = z3 * z2; z7 = z5 * z2; z9 = z7 * z2
    g1 = (z3 + z) / 4
    g2 = (5 * z5 + 16 * z3 + 3 * z) / 96
    g3 = (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / 384
    g4 = (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / 92160
    return z + g1 / df + g2 / (df * df) + g3 / (df * df * df) + g4 / (df * df * df * df)


def inverse(target, df, hi, or_equal=False):
    # StudentT.InverseCornishFisher's bisection, for target = |t| > 0.
    lo = 0.0
    while True:
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        e = expansion(mid, df)
        if (e <= target) if or_equal else (e < target):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def main():
    draws = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    rng = random.Random(1)
    bracket_differs = equal_differs = 0
    most_ulps = 0.0
    for _ in range(draws):
        df = 1000 * 10 ** rng.uniform(0, 13) + rng.random()  # past ExactUpTo, up to 1e16
        t = 10 ** rng.uniform(-12, 2.2)                        # 1e-12 to 160
        z = inverse(t, df, min(t, 40.0))
        if inverse(t, df, max(t, 40.0)) != z and z < 38:
            bracket_differs += 1
        z_or_equal = inverse(t, df, min(t, 40.0), or_equal=True)
        if z_or_equal != z:
            equal_differs += 1
            most_ulps = max(most_ulps, abs(z_or_equal - z) / math.ulp(z))
    print(f"{draws} draws (t from 1e-12 to 160, ν from 1000 to 1e16)")
    print(f"Math.Max bracket: {bracket_differs} differ below z = 38")
    print(f"<= for <: {equal_differs} differ, by at most {most_ulps:g} ulps of z")
    return 1 if bracket_differs else 0


if __name__ == "__main__":
    sys.exit(main())
