#!/usr/bin/env python3
"""Where a render's error against the truth lies on a field of steps (issue
36 item 1, docs/benchmarks/long-shadows.md "Where the city's error lies"):
the texels classed by their 3 x 3 neighbourhood's heights (clamped at the
field's border) - flat where its range is below FLAT, else at a step's
foot (the texel in the lowest third of that range), its top (the highest
third) or between - and per class the share of the texels, the mean
|error| and mean signed error (RENDER - TRUTH over every channel, divided
by NORM, the unshadowed maximum `hfshade compare` prints) and the share of
the whole |error|.
usage: tools/pfm_wall_classes.py RENDER.pfm TRUTH.pfm HEIGHTS.pfm NORM [FLAT]"""
import sys

from pfm_rel_mean import read_pfm


def texel_class(z, w, h, i, j, flat):
    """'flat', 'foot', 'top' or 'between' for texel (i, j)."""
    near = [z[min(max(j + dj, 0), h - 1) * w + min(max(i + di, 0), w - 1)]
            for dj in (-1, 0, 1) for di in (-1, 0, 1)]
    lo, hi = min(near), max(near)
    if hi - lo < flat:
        return 'flat'
    pos = (z[j * w + i] - lo) / (hi - lo)
    return 'foot' if pos < 1 / 3 else ('top' if pos > 2 / 3 else 'between')


def main():
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    (wr, hr, r), (wt, ht, t), (w, h, z) = (read_pfm(p) for p in sys.argv[1:4])
    norm = float(sys.argv[4])
    flat = float(sys.argv[5]) if len(sys.argv) == 6 else 0.01
    if (wr, hr, len(r)) != (wt, ht, len(t)) or (wr, hr) != (w, h) or len(z) != w * h:
        sys.exit('RENDER and TRUTH must be images of one size, HEIGHTS one channel of it')
    if not norm > 0:
        sys.exit('NORM must be positive')
    c = len(r) // (w * h)
    stats = {name: [0, 0.0, 0.0] for name in ('flat', 'foot', 'between', 'top')}
    total = 0.0
    for j in range(h):
        for i in range(w):
            k = (j * w + i) * c
            d = sum(r[k + q] - t[k + q] for q in range(c)) / (c * norm)
            e = sum(abs(r[k + q] - t[k + q]) for q in range(c)) / (c * norm)
            s = stats[texel_class(z, w, h, i, j, flat)]
            s[0] += 1
            s[1] += e
            s[2] += d
            total += e
    print('| class | texels | mean abs | mean signed | share of the error |')
    print('|---|---|---|---|---|')
    for name, (n, e, d) in stats.items():
        if n:
            print('| %s | %.3f | %.3e | %+.3e | %.3f |' %
                  (name, n / (w * h), e / n, d / n, e / total if total > 0 else 0.0))


if __name__ == '__main__':
    main()
