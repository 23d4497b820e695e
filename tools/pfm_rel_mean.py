#!/usr/bin/env python3
"""Relative mean error of two PFM images: sum |a - b| / sum |b| over every
channel (b the reference).  SPEC's metrics divide by the largest unshadowed
value, which next to a local light is far above the typical texel; this
column says how wrong the light is where it lands.
usage: tools/pfm_rel_mean.py A.pfm REFERENCE.pfm"""
import array
import sys


def read_pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        if kind not in (b'PF', b'Pf'):
            sys.exit('%s: not a PFM file' % path)
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = array.array('f')
        data.frombytes(f.read())
    if scale > 0:  # big-endian
        data.byteswap()
    return w, h, data


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    wa, ha, a = read_pfm(sys.argv[1])
    wb, hb, b = read_pfm(sys.argv[2])
    if (wa, ha, len(a)) != (wb, hb, len(b)):
        sys.exit('%s and %s differ in size' % (sys.argv[1], sys.argv[2]))
    ref = sum(abs(y) for y in b)
    err = sum(abs(x - y) for x, y in zip(a, b))
    print('%.3e' % (err / ref if ref > 0 else 0.0))


if __name__ == '__main__':
    main()
