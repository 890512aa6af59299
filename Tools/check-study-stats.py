#!/usr/bin/env python3
"""Independent check of `pseudohaptic psychometric` and `compare` (issue 11), with mpmath at 40 digits.

Usage:
  python3 Tools/check-study-stats.py generate DIR [SEED]  # writes DIR/trials.csv and DIR/scores.csv (seeded)
  python3 Tools/check-study-stats.py psychometric T.csv FITS.csv
  python3 Tools/check-study-stats.py compare S.csv COMPARISONS.csv

Recomputes every number from the input files with its own code (probit maximum likelihood by Newton's
method in (a, b) at 40 digits; t, normal and chi-square tails from mpmath's incomplete beta and gamma
functions; the exact signed-rank distribution by counting subsets) and prints the largest relative
differences. Needs only Python 3 and mpmath. Not part of the test suite.
"""
import csv, math, random, sys
from fractions import Fraction
from collections import OrderedDict, defaultdict
import mpmath as mp

mp.mp.dps = 40

def rel(a, b):
    a, b = float(a), float(b)
    if a == b: return 0.0
    return abs(a - b) / max(abs(b), 1e-300)

def Phi(z): return mp.ncdf(z)

# ---------------------------------------------------------------- psychometric
def probit_fit(levels):
    """levels: list of (x, n, k). Returns (mu, sigma, deviance) or None when no finite maximum with b > 0."""
    xs = [mp.mpf(x) for x, _, _ in levels]
    N = sum(n for _, n, _ in levels)
    mean = sum(mp.mpf(x) * n for x, n, _ in levels) / N
    sd = mp.sqrt(sum(n * (mp.mpf(x) - mean) ** 2 for x, n, _ in levels) / N)
    z = [(x - mean) / sd for x in xs]
    def ll(a, b):
        s = mp.mpf(0)
        for zi, (_, n, k) in zip(z, levels):
            e = a + b * zi
            if k: s += k * mp.log(Phi(e))
            if n - k: s += (n - k) * mp.log(Phi(-e))
        return s
    a, b = mp.mpf(0), mp.mpf(1)
    cur = ll(a, b)
    for _ in range(300):
        ga = gb = haa = hab = hbb = mp.mpf(0)
        for zi, (_, n, k) in zip(z, levels):
            e = a + b * zi
            phi = mp.npdf(e)
            m1 = phi / Phi(e); m0 = phi / Phi(-e)
            g = k * m1 - (n - k) * m0
            h = -k * m1 * (e + m1) - (n - k) * m0 * (m0 - e)
            ga += g; gb += g * zi; haa += h; hab += h * zi; hbb += h * zi * zi
        det = haa * hbb - hab * hab
        da = -(hbb * ga - hab * gb) / det
        db = -(haa * gb - hab * ga) / det
        t = mp.mpf(1)
        while True:
            na, nb = a + t * da, b + t * db
            try:
                new = ll(na, nb)
            except (ValueError, ZeroDivisionError):
                new = mp.mpf('-inf')
            if new >= cur or t < mp.mpf(10) ** -30: break
            t /= 2
        a, b, cur = na, nb, new
        if abs(da) + abs(db) < mp.mpf(10) ** -30: break
    if b <= 0: return None
    mu = mean - sd * a / b
    sigma = sd / b
    dev = mp.mpf(0)
    for zi, (_, n, k) in zip(z, levels):
        e = a + b * zi
        if k: dev += k * mp.log(k / (n * Phi(e)))
        if n - k: dev += (n - k) * mp.log((n - k) / (n * Phi(-e)))
    return mu, sigma, 2 * dev

def check_psychometric(trials_path, fits_path):
    groups = OrderedDict()
    with open(trials_path, newline='') as f:
        for row in csv.DictReader(f):
            key = (row['participant'].strip(), (row.get('condition') or '').strip(), float(row['standard']))
            groups.setdefault(key, defaultdict(lambda: [0, 0]))
            c = groups[key][float(row['comparison'])]
            c[0] += 1; c[1] += int(row['response'])
    worst = {'pse': 0, 'sigma': 0, 'jnd': 0, 'deviance': 0}
    estimable = other = 0
    with open(fits_path, newline='') as f:
        for row in csv.DictReader(f):
            key = (row['participant'], row['condition'], float(row['standard']))
            levels = sorted((x, n, k) for x, (n, k) in groups[key].items())
            K = sum(k for _, _, k in levels); N = sum(n for _, n, _ in levels)
            x0 = max([x for x, n, k in levels if n - k > 0], default=-math.inf)
            x1 = min([x for x, n, k in levels if k > 0], default=math.inf)
            y1 = max([x for x, n, k in levels if k > 0], default=-math.inf)
            y0 = min([x for x, n, k in levels if n - k > 0], default=math.inf)
            degenerate = len(levels) < 2 or K == 0 or K == N or x0 <= x1 or y1 <= y0
            fit = None if degenerate else probit_fit(levels)
            if row['estimable'] != 'yes':
                other += 1
                if fit is not None: print('MISMATCH: not estimable but the check fits', key, row['estimable'])
                continue
            estimable += 1
            if fit is None:
                print('MISMATCH: estimable but the check finds no maximum', key); continue
            mu, sigma, dev = fit
            worst['pse'] = max(worst['pse'], rel(row['pse'], mu))
            worst['sigma'] = max(worst['sigma'], rel(row['sigma'], sigma))
            worst['jnd'] = max(worst['jnd'], rel(row['jnd'], sigma * mp.sqrt(2) * mp.erfinv(mp.mpf(1) / 2)))
            worst['deviance'] = max(worst['deviance'], abs(float(row['deviance']) - float(dev)) / max(1.0, abs(float(dev))))
    print(f'psychometric: {estimable} estimable fits, {other} not estimable; largest relative differences:',
          ', '.join(f'{k} {v:.2e}' for k, v in worst.items()))

# ---------------------------------------------------------------- compare
def t_tail2(t, df):
    t = mp.mpf(t)
    return mp.betainc(mp.mpf(df) / 2, mp.mpf(1) / 2, 0, df / (df + t * t), regularized=True)

def t_quantile975(df):
    return mp.findroot(lambda q: t_tail2(q, df) / 2 - mp.mpf('0.025'), 2)

def avg_ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    ranks = [0] * len(values); ties = 0; i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]: j += 1
        for q in range(i, j + 1): ranks[order[q]] = mp.mpf(i + j) / 2 + 1
        t = j - i + 1; ties += t ** 3 - t; i = j + 1
    return ranks, ties

def paired(a, b):
    """a, b: the scores as the file writes them (decimal strings)."""
    d = [float(y) - float(x) for x, y in zip(a, b)]   # the t test in doubles, as the tool computes it
    # The signed-rank test on the exact decimal differences: its ties and zeros are the data's (3.4 − 3.2 = 3.6 − 3.4),
    # whatever a subtraction in doubles rounds them to.
    exact = [Fraction(y) - Fraction(x) for x, y in zip(a, b)]
    n = len(d); out = {}
    if n >= 2:
        m = mp.fsum(d) / n
        sd = mp.sqrt(mp.fsum((v - m) ** 2 for v in d) / (n - 1))
        if sd > 1e-12 * max(1, abs(m)):
            t = m / (sd / mp.sqrt(n))
            out.update(t=t, t_p=t_tail2(t, n - 1), dz=m / sd)
            q = t_quantile975(n - 1)
            out.update(diff_lo=m - q * sd / mp.sqrt(n), diff_hi=m + q * sd / mp.sqrt(n))
    if n >= 1: out['mean_diff'] = mp.fsum(d) / n
    nz = [v for v in exact if v != 0]
    N = len(nz)
    if N:
        ranks, ties = avg_ranks([abs(v) for v in nz])
        w = mp.fsum(r for r, v in zip(ranks, nz) if v > 0)
        out['w'] = w
        var = mp.mpf(N * (N + 1) * (2 * N + 1)) / 24 - mp.mpf(ties) / 48
        z = None
        if var > 0:
            c = w - mp.mpf(N * (N + 1)) / 4
            z = (c - (mp.sign(c) / 2)) / mp.sqrt(var)
            out['r'] = z / mp.sqrt(N)
        if N <= 25 and ties == 0:
            counts = [0] * (N * (N + 1) // 2 + 1); counts[0] = 1
            for r in range(1, N + 1):
                for s in range(len(counts) - 1, r - 1, -1): counts[s] += counts[s - r]
            wi = int(w)
            below = sum(counts[:wi + 1]); above = sum(counts[wi:])
            out['w_p'] = min(mp.mpf(1), 2 * mp.mpf(min(below, above)) / 2 ** N)
        elif z is not None:
            out['w_p'] = min(mp.mpf(1), 2 * min(Phi(z), 1 - Phi(z)))
    return out

def friedman(rows):
    n, k = len(rows), len(rows[0])
    R = [mp.mpf(0)] * k; ties = 0
    for row in rows:
        r, t = avg_ranks(row); ties += t
        R = [x + y for x, y in zip(R, r)]
    num = mp.fsum((x - mp.mpf(n * (k + 1)) / 2) ** 2 for x in R)
    den = mp.mpf(n * k * (k + 1)) - mp.mpf(ties) / (k - 1)
    if den <= 0: return None
    q = 12 * num / den
    return q, mp.gammainc(mp.mpf(k - 1) / 2, q / 2, mp.inf, regularized=True)

def holm(ps):
    idx = sorted([i for i, p in enumerate(ps) if p is not None], key=lambda i: (ps[i], i))
    out = [None] * len(ps); run = 0; m = len(idx)
    for j, i in enumerate(idx):
        run = max(run, min(1, (m - j) * ps[i])); out[i] = run
    return out

def check_compare(scores_path, comparisons_path):
    data = defaultdict(dict); qs = []; conds = []
    with open(scores_path, newline='') as f:
        for row in csv.DictReader(f):
            q, c = row['questionnaire'].strip(), row['condition'].strip()
            if q not in qs: qs.append(q)
            if c not in conds: conds.append(c)
            data[(q, c)][row['participant'].strip()] = row['score'].strip() if row['score'].strip() else None
    expected = {}
    for q in qs:
        cs = [c for c in conds if (q, c) in data]
        if len(cs) < 2: continue
        if len(cs) >= 3:
            people = sorted(set().union(*[data[(q, c)].keys() for c in cs]))
            rows = [[Fraction(data[(q, c)][p]) for c in cs] for p in people if all(data[(q, c)].get(p) is not None for c in cs)]
            fr = friedman(rows) if rows else None
            expected[(q, '*', '*')] = {'n': len(rows), **({'t': fr[0], 't_p': fr[1]} if fr else {})}
        pair_keys = []
        for i in range(len(cs)):
            for j in range(i + 1, len(cs)):
                a, b = data[(q, cs[i])], data[(q, cs[j])]
                people = [p for p in a if a[p] is not None and b.get(p) is not None]
                # the tool pairs in natural participant order; the statistics do not depend on it except through
                # floating sums, which the check does at 40 digits
                res = paired([a[p] for p in people], [b[p] for p in people]); res['n'] = len(people)
                expected[(q, cs[i], cs[j])] = res; pair_keys.append((q, cs[i], cs[j]))
        ps = [expected[k].get('w_p') for k in pair_keys]
        adj = holm(ps) if len(cs) >= 3 else ps
        for k, p in zip(pair_keys, adj):
            if p is not None: expected[k]['p_holm'] = p
    worst = defaultdict(float); seen = 0
    with open(comparisons_path, newline='') as f:
        for row in csv.DictReader(f):
            key = (row['questionnaire'], row['condition_a'], row['condition_b'])
            exp = expected.pop(key, None)
            if exp is None: print('MISMATCH: unexpected row', key); continue
            seen += 1
            for col in ['n', 'mean_diff', 'diff_lo', 'diff_hi', 't', 't_p', 'w', 'w_p', 'dz', 'r', 'p_holm']:
                have = row[col]
                if col not in exp:
                    if have != '': print('MISMATCH: the tool gives', col, have, 'where the check has none', key)
                    continue
                if have == '': print('MISMATCH: the tool leaves', col, 'empty', key, float(exp[col])); continue
                d = abs(float(have) - float(exp[col])) / max(abs(float(exp[col])), 1e-300) if col not in ('diff_lo', 'diff_hi', 'mean_diff') else abs(float(have) - float(exp[col])) / max(abs(float(exp[col])), 1e-12)
                worst[col] = max(worst[col], d)
    for k in expected: print('MISMATCH: row missing', k)
    print(f'compare: {seen} rows; largest relative differences:', ', '.join(f'{k} {v:.2e}' for k, v in sorted(worst.items())))

# ---------------------------------------------------------------- data
def generate(folder, seed=20261123):
    rnd = random.Random(seed)
    with open(f'{folder}/trials.csv', 'w', newline='') as f:
        w = csv.writer(f, lineterminator='\n'); w.writerow(['participant', 'condition', 'standard', 'comparison', 'response'])
        for p in range(1, 41):
            for cond, shift in (('off', 0.0), ('on', 0.06)):
                std = rnd.choice([0.5, 1.0])
                pse = std * (1 + shift + rnd.gauss(0, 0.04)); sigma = std * rnd.uniform(0.04, 0.2)
                reps = rnd.choice([4, 8, 12]); lapse = rnd.choice([0, 0, 0.03])
                for lv in [0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3]:
                    x = round(std * lv, 6)
                    for _ in range(reps):
                        pr = lapse + (1 - 2 * lapse) * float(Phi((x - pse) / sigma))
                        w.writerow([f'P{p}', cond, std, x, 1 if rnd.random() < pr else 0])
        for x, r in ((0.9, 0), (1.1, 1), (1.0, 0), (1.0, 1)): w.writerow(['Dsep', 'off', 1, x, r])
        for x in (0.9, 1.0, 1.1): w.writerow(['Dall', 'off', 1, x, 1])
    with open(f'{folder}/scores.csv', 'w', newline='') as f:
        w = csv.writer(f, lineterminator='\n'); w.writerow(['participant', 'condition', 'questionnaire', 'score'])
        for q, k, n, step in (('weight-detection', 2, 12, 0.1), ('immersion', 3, 30, 0.1), ('self-assessment', 4, 9, 1), ('ties', 3, 40, 0.5), ('tiny', 2, 2, 0.1)):
            for p in range(1, n + 1):
                base = rnd.uniform(2, 4)
                for c in range(k):
                    if rnd.random() < 0.05: w.writerow([f'P{p}', f'c{c}', q, '']); continue
                    v = round((base + c * 0.2 + rnd.gauss(0, 0.4)) / step) * step
                    w.writerow([f'P{p}', f'c{c}', q, repr(round(v, 10))])

if __name__ == '__main__':
    cmd = sys.argv[1] if len(sys.argv) > 1 else ''
    if cmd == 'generate': generate(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 20261123)
    elif cmd == 'psychometric': check_psychometric(sys.argv[2], sys.argv[3])
    elif cmd == 'compare': check_compare(sys.argv[2], sys.argv[3])
    else: print(__doc__); sys.exit(2)
