"""Shared by the Python module's tests (tests/python.cmake runs each file
with /usr/bin/python3, PYTHONPATH=tools/python, HFSHADE_LIBRARY and
HFSHADE_GIS_LIBRARY at the build tree's libraries, HFSHADE_CLI at the
build's `hfshade`).  Exit 77 (ctest: skipped) with the reason when numpy
or cffi is missing, or what a test needs (GDAL, a GLES context)."""
import os
import subprocess
import sys
import tempfile
import unittest

SKIP = 77


def skip(reason):
    print(f"SKIP: {reason}")
    sys.exit(SKIP)


try:
    import numpy as np
    import cffi  # noqa: F401
except ImportError as e:
    skip(f"{e.name} is not installed (Debian: python3-numpy python3-cffi)")

import hfshade  # noqa: E402

CLI = os.environ.get("HFSHADE_CLI", "hfshade")


def gdal():
    try:
        from osgeo import gdal as g
    except ImportError:
        return None
    g.UseExceptions()
    return g


def gdal_or_skip():
    """osgeo.gdal, or the test class skipped (SkipTest) where it is missing."""
    g = gdal()
    if g is None:
        raise unittest.SkipTest("osgeo.gdal is not installed (Debian: python3-gdal)")
    return g


def run_cli(*args):
    """Runs `hfshade ARGS`; its stderr on failure in the exception."""
    p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if p.returncode != 0:
        raise AssertionError(f"hfshade {' '.join(map(str, args))}: exit {p.returncode}: "
                             f"{p.stderr.strip()}")
    return p.stdout


def write_pfm(path, a):
    """a (H, W) grey or (H, W, 3) RGB as this project's PFM: first row
    stored = row 0 (SPEC "File row order"), little-endian (scale -1)."""
    a = np.asarray(a, dtype="<f4")
    kind = b"PF" if a.ndim == 3 else b"Pf"
    with open(path, "wb") as f:
        f.write(kind + b"\n%d %d\n-1.0\n" % (a.shape[1], a.shape[0]))
        f.write(np.ascontiguousarray(a).tobytes())


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    shape = (h, w, 3) if kind == b"PF" else (h, w)
    return data.reshape(shape).astype(np.float32)


def same_bits(a, b):
    """Equal bit for bit (NaN-safe, -0 != +0)."""
    a, b = np.ascontiguousarray(a, np.float32), np.ascontiguousarray(b, np.float32)
    return a.shape == b.shape and np.array_equal(a.view(np.uint32), b.view(np.uint32))


def terrain(h=48, w=64, seed=7):
    """A small non-square field with relief: ridges, a pit and noise."""
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    z = (6.0 * np.sin(x / 7.0) * np.cos(y / 9.0) + 0.08 * x * np.sin(y / 5.0)
         - 8.0 * np.exp(-((x - 40) ** 2 + (y - 20) ** 2) / 30.0))
    z += np.random.default_rng(seed).normal(0.0, 0.3, z.shape)
    return z.astype(np.float32)


def sky(h=32, w=64, sun=(20, 9), sun_value=400.0):
    """A small equirectangular map: a gradient sky, a darker ground and a
    bright sun of a few texels (column, row)."""
    j = (np.arange(h) + 0.5) / h
    base = np.where(j < 0.5, 0.6 + 0.8 * (0.5 - j), 0.15)[:, None]
    m = np.empty((h, w, 3), dtype=np.float32)
    m[..., 0] = base * 0.8
    m[..., 1] = base * 0.9
    m[..., 2] = base * 1.2 + 0.01 * np.arange(w)[None, :] / w
    c, r = sun
    m[r:r + 2, c:c + 2] = (sun_value, 0.9 * sun_value, 0.7 * sun_value)
    return m


def gles_available():
    try:
        with hfshade.Renderer("gles"):
            return True
    except hfshade.Error as e:
        if e.status in ("context", "unsupported") and os.environ.get("HFS_REQUIRE_GL") != "1":
            return False
        raise


class TempDir(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp, name)


def main():
    """unittest's main, exit 77 when every test skipped."""
    prog = unittest.main(exit=False, verbosity=2)
    r = prog.result
    if not r.wasSuccessful():
        sys.exit(1)
    if r.testsRun and len(r.skipped) == r.testsRun:
        print(f"SKIP: {r.skipped[0][1]}")
        sys.exit(SKIP)
    sys.exit(0)
