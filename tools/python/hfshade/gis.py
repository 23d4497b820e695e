"""GIS rasters of a DEM held as a numpy array: sky-view factor, horizon
angle, openness (libhfshade_gis, the code of `hfshade svf | horizon |
openness`; docs/GIS.md): on the same heights, cell size and options the
values equal the commands' GeoTIFFs bit for bit.

Conventions (those of rasterio and richdem): the DEM is a 2-D array, row
0 = north, column 0 = west, row-major; cells square, `cell_size` metres;
nodata given as a numpy masked array's mask, as NaN/Inf, or as the value
`nodata=`.  Holes are filled (push-pull, as the commands fill them) only to
compute their neighbours.  Every product comes back as a float32
numpy.ma.MaskedArray of the DEM's shape, masked where the DEM has no data
(and where a product has no value: openness of a texel whose every
direction leaves the DEM at once); the masked cells hold the product's
nodata value (the DEM's `nodata` when it cannot be a value of the
product, else -9999), which is also the array's fill_value, so
`.filled()` gives what the command writes.  The mask is always an array
(never numpy.ma.nomask).  Degrees throughout.
"""
import numpy as np

from ._errors import check, float32_array, integer, new_error, number
from ._ffi import ffi, gis_lib
from .render import Renderer

_SVF, _HORIZON, _OPENNESS = 0, 1, 2
RADIUS_DEFAULT = -1.0


def _cell(cell_size):
    if isinstance(cell_size, (tuple, list)):
        if len(cell_size) != 2:
            raise ValueError("cell_size: expected metres, or (x, y) metres")
        cx = number("cell_size", cell_size[0], 0.0)
        cy = number("cell_size", abs(cell_size[1]), 0.0)
        if abs(cx - cy) > 1e-6 * max(cx, cy):
            raise ValueError(f"cell_size: cells of {cx:g} x {cy:g} m are not square (resample "
                             "the DEM to square cells first, e.g. gdalwarp -tr)")
        cell_size = cx
    cell = number("cell_size", cell_size, 0.0)
    if cell <= 0.0:
        raise ValueError(f"cell_size: {cell_size!r} is not a size above 0 metres")
    return cell


class _Dem:
    """The DEM as hfs_gis_dem, its buffers kept alive."""

    def __init__(self, dem, cell_size, zscale, nodata):
        self.z = float32_array("dem", dem, ndim=2)
        if self.z.shape[0] < 2 or self.z.shape[1] < 2:
            raise ValueError(f"dem: expected at least 2x2 heights, got shape {self.z.shape}")
        self.shape = self.z.shape
        mask = np.ma.getmaskarray(dem) if isinstance(dem, np.ma.MaskedArray) else None
        self.hole = None if mask is None else np.ascontiguousarray(mask, dtype=np.uint8)
        d = self.c = ffi.new("hfs_gis_dem *")
        d.width, d.height = self.shape[1], self.shape[0]
        d.z = self._zbuf = ffi.from_buffer("float[]", self.z)
        if self.hole is not None:
            d.hole = self._hbuf = ffi.from_buffer("unsigned char[]", self.hole)
        if nodata is not None:
            if isinstance(nodata, bool) or not isinstance(nodata, (int, float, np.number)):
                raise TypeError(f"nodata: expected a number, got {type(nodata).__name__}")
            d.has_nodata, d.nodata = 1, float(nodata)
        d.cell = _cell(cell_size)
        d.zscale = number("zscale", zscale, 1e-9, 1e6)

    def holes(self):
        """Where the DEM has no data, as the library judges it."""
        h = ~np.isfinite(self.z)
        if self.hole is not None:
            h |= self.hole.astype(bool)
        if self.c.has_nodata:
            h |= self.z == np.float32(self.c.nodata)
        return h

    def masked(self, out, product):
        """out (the DEM's shape, or a stack of them) masked where there is
        no data; fill_value the product's nodata."""
        fill = float(gis_lib().hfs_gis_nodata(self.c, product))
        mask = self.holes() | (out == np.float32(fill))  # broadcast over a stack
        return np.ma.MaskedArray(out, mask=mask, fill_value=np.float32(fill))


def _radius(radius):
    if radius is None:
        return RADIUS_DEFAULT
    return number("radius", radius, 0.0, 1e9)


def _run(renderer, backend, fn):
    if renderer is not None:
        if not isinstance(renderer, Renderer):
            raise TypeError("renderer: expected an hfshade.Renderer")
        return fn(renderer.handle)
    with Renderer(backend) as r:
        return fn(r.handle)


def svf(dem, cell_size, directions=16, radius=None, kind="zaksek", zscale=1.0, nodata=None,
        backend="gles", renderer=None):
    """Sky-view factor, 0..1 (1 on a plane), as `hfshade svf`.

    kind: "zaksek" (Zaksek et al. 2011: 1 - mean sin(max(gamma, 0)), the
    default) or "lambertian" (Haentzschel et al. 2005, SAGA's:
    mean cos^2(max(gamma, 0)), `--lambertian`).  directions: 1..1024
    azimuths equally spaced from east (default 16).  radius: search
    distance in metres (None or 0: the whole DEM).  zscale: heights times
    zscale are metres.  backend: "gles" (the command's default), "cpu",
    "truth"; or renderer: an hfshade.Renderer to reuse."""
    if kind not in ("zaksek", "lambertian"):
        raise ValueError(f"kind: {kind!r} is not zaksek or lambertian")
    d = _Dem(dem, cell_size, zscale, nodata)
    n = integer("directions", directions, 1, 1024)
    rad = _radius(radius)
    out = np.empty(d.shape, dtype=np.float32)

    def go(r):
        err = new_error()
        check(gis_lib().hfs_gis_svf(r, d.c, n, kind == "lambertian", rad,
                                    ffi.from_buffer("float[]", out), err), err)
    _run(renderer, backend, go)
    return d.masked(out, _SVF)


def horizon(dem, cell_size, azimuth, convention="ccw-east", radius=None, zscale=1.0,
            nodata=None, backend="gles", renderer=None):
    """Horizon elevation angle in degrees >= 0 (GRASS r.horizon -d: 0 where
    nothing rises above the horizontal), as `hfshade horizon`.

    azimuth: degrees, or a sequence of them (then an (n, H, W) array);
    convention: "ccw-east" (counter-clockwise from east, r.horizon's, the
    default) or "compass" (clockwise from north).  radius: metres (None or
    0: the whole DEM).  Other arguments as svf()."""
    if convention not in ("ccw-east", "compass"):
        raise ValueError(f"convention: {convention!r} is not ccw-east or compass")
    d = _Dem(dem, cell_size, zscale, nodata)
    many = np.ndim(azimuth) == 1
    azimuths = [number("azimuth", a, -1e6, 1e6) for a in (azimuth if many else [azimuth])]
    if many and not 1 <= len(azimuths) <= 1024:
        raise ValueError(f"azimuth: {len(azimuths)} azimuths, 1..1024 allowed")
    rad = _radius(radius)
    out = np.empty((len(azimuths),) + d.shape, dtype=np.float32)

    def go(r):
        for k, a in enumerate(azimuths):
            err = new_error()
            check(gis_lib().hfs_gis_horizon(r, d.c, a, convention == "compass", rad,
                                            ffi.from_buffer("float[]", out[k]), err), err)
    _run(renderer, backend, go)
    result = d.masked(out, _HORIZON)
    return result if many else result[0]


def openness(dem, cell_size, directions=8, radius=None, zscale=1.0, nodata=None,
             backend="gles", renderer=None):
    """Positive and negative openness (Yokoyama et al. 2002), degrees
    (90 on a plane), as `hfshade openness`'s bands 1 and 2: returns
    (positive, negative).

    directions: 1..1024 (default 8); radius: metres, None = the command's
    default of 10 cells (openness is a local measure), 0 = the whole DEM.
    Other arguments as svf()."""
    d = _Dem(dem, cell_size, zscale, nodata)
    n = integer("directions", directions, 1, 1024)
    rad = _radius(radius)
    pos = np.empty(d.shape, dtype=np.float32)
    neg = np.empty(d.shape, dtype=np.float32)

    def go(r):
        err = new_error()
        check(gis_lib().hfs_gis_openness(r, d.c, n, rad, ffi.from_buffer("float[]", pos),
                                         ffi.from_buffer("float[]", neg), err), err)
    _run(renderer, backend, go)
    return d.masked(pos, _OPENNESS), d.masked(neg, _OPENNESS)


__all__ = ["svf", "horizon", "openness"]
