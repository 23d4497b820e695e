#!/usr/bin/env python3
"""The range of a PFM's values: its smallest and largest finite value,
how many values lie below 0 and how many are not finite, of all of them
(every channel).  Radiance is never negative, so a count below 0 shows
where a renderer's integrals cross zero.
usage: tools/pfm_range.py IMAGE.pfm"""
import math
import sys

from pfm_rel_mean import read_pfm


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    _, _, data = read_pfm(sys.argv[1])
    finite = [v for v in data if math.isfinite(v)]
    below = sum(1 for v in finite if v < 0.0)
    lo = min(finite) if finite else float('nan')
    hi = max(finite) if finite else float('nan')
    print(f'values {len(data)} min {lo:.4g} max {hi:.4g} below_zero {below} '
          f'nonfinite {len(data) - len(finite)}')


if __name__ == '__main__':
    main()
