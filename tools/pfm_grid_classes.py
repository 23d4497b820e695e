#!/usr/bin/env python3
"""Where a sub-sampled gather's indirect light departs from the every-texel
one, by texel class (issue 36 item 4, docs/benchmarks/bounces.md): with
DIRECT.pfm the frame without bounces, EVERY.pfm the bounce frame where
every texel is a receiver and GRID.pfm the one gathered every STEP texels,
the mean signed difference (GRID - DIRECT) - (EVERY - DIRECT), over the
largest every-texel indirect value (first channel), on the grid's
receivers, between them, and over the height field's pits (positive
discrete Laplacian) and peaks (the rest), borders left out of those two.
usage: tools/pfm_grid_classes.py DIRECT.pfm EVERY.pfm GRID.pfm HEIGHTS.pfm STEP"""
import sys

from pfm_rel_mean import read_pfm


def first_channel(path):
    w, h, data = read_pfm(path)
    c = len(data) // (w * h)
    return w, h, data[::c]


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    images = [first_channel(p) for p in sys.argv[1:5]]
    step = int(sys.argv[5])
    w, h = images[0][0], images[0][1]
    if any((iw, ih) != (w, h) for iw, ih, _ in images) or step < 1:
        sys.exit('the four images must share one size, STEP >= 1')
    direct, every, grid, z = (d for _, _, d in images)
    indirect = [e - d for e, d in zip(every, direct)]
    norm = max(indirect)
    if not norm > 0:
        sys.exit('no indirect light in %s' % sys.argv[2])
    diff = [(g - e) / norm for g, e in zip(grid, every)]
    classes = {'receivers': [], 'between': [], 'pits': [], 'peaks': []}
    for j in range(h):
        for i in range(w):
            k = j * w + i
            on = i % step == 0 and j % step == 0
            classes['receivers' if on else 'between'].append(diff[k])
            if 0 < i < w - 1 and 0 < j < h - 1:
                lap = z[k - 1] + z[k + 1] + z[k - w] + z[k + w] - 4 * z[k]
                classes['pits' if lap > 0 else 'peaks'].append(diff[k])
    for name, v in classes.items():
        if v:
            print('%-9s %6d texels  mean %+.4f  mean |.| %.4f' %
                  (name, len(v), sum(v) / len(v), sum(abs(x) for x in v) / len(v)))


if __name__ == '__main__':
    main()
