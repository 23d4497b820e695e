"""GIS rasters of a DEM held as a numpy array: sky-view factor, horizon
angle, openness, the sun at an instant and insolation over a period
(libhfshade_gis, the code of `hfshade svf | horizon | openness | sun |
insolation`; docs/GIS.md): on the same heights, cell size and options the
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

The sun's instants are timezone-aware datetime.datetime objects or ISO
8601 strings with their offset ("2026-06-21T09:30+02:00", "...Z"): as the
command refuses a date-time without one, no time zone is guessed.
"""
import datetime as _dt
import math

import numpy as np

from ._errors import check, float32_array, integer, new_error, number
from ._ffi import ffi, gis_lib
from .envmap import env_map_array
from .render import Renderer

_SVF, _HORIZON, _OPENNESS, _SUN, _INSOLATION = 0, 1, 2, 3, 4
RADIUS_DEFAULT = -1.0
_EPOCH = _dt.datetime(1970, 1, 1, tzinfo=_dt.timezone.utc)
_YEARS = (1900, 2100)  # solar_position.h's HFS_SOLAR_YEAR_MIN..MAX


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


def _run(renderer, backend, fn, method="exact"):
    """fn(the renderer's handle), or with method "sweep" fn(NULL): the
    library's horizons by the sweep (docs/GIS.md "The sweep")."""
    if method not in ("exact", "sweep"):
        raise ValueError(f"method: {method!r} is not exact or sweep")
    if method == "sweep":
        if renderer is not None or backend == "truth":
            raise ValueError("method: 'sweep' takes no renderer and no truth backend "
                             "(it runs on the host)")
        return fn(ffi.NULL)
    if renderer is not None:
        if not isinstance(renderer, Renderer):
            raise TypeError("renderer: expected an hfshade.Renderer")
        return fn(renderer.handle)
    with Renderer(backend) as r:
        return fn(r.handle)


def svf(dem, cell_size, directions=16, radius=None, kind="zaksek", zscale=1.0, nodata=None,
        backend="gles", renderer=None, method="exact"):
    """Sky-view factor, 0..1 (1 on a plane), as `hfshade svf`.

    kind: "zaksek" (Zaksek et al. 2011: 1 - mean sin(max(gamma, 0)), the
    default) or "lambertian" (Haentzschel et al. 2005, SAGA's:
    mean cos^2(max(gamma, 0)), `--lambertian`).  directions: 1..1024
    azimuths equally spaced from east (default 16).  radius: search
    distance in metres (None or 0: the whole DEM).  zscale: heights times
    zscale are metres.  backend: "gles" (the command's default), "cpu",
    "truth"; or renderer: an hfshade.Renderer to reuse.  method: "exact"
    (the default) or "sweep" (`--method sweep`: the horizons on the host by
    a line sweep, no renderer, the whole DEM only: radius None or 0)."""
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
    _run(renderer, backend, go, method)
    return d.masked(out, _SVF)


def horizon(dem, cell_size, azimuth, convention="ccw-east", radius=None, zscale=1.0,
            nodata=None, backend="gles", renderer=None, method="exact"):
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
    _run(renderer, backend, go, method)
    result = d.masked(out, _HORIZON)
    return result if many else result[0]


def openness(dem, cell_size, directions=8, radius=None, zscale=1.0, nodata=None,
             backend="gles", renderer=None, method="exact"):
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
    _run(renderer, backend, go, method)
    return d.masked(pos, _OPENNESS), d.masked(neg, _OPENNESS)


def _instant(name, value):
    """value (an aware datetime, or an ISO 8601 string with its offset) as
    seconds since 1970-01-01T00:00:00Z: whole seconds exactly (integer
    arithmetic), which the library turns into the command's Julian day."""
    if isinstance(value, str):
        text = value.strip()
        if text[-1:] in ("Z", "z"):  # Python < 3.11 reads no "Z"
            text = text[:-1] + "+00:00"
        try:
            value = _dt.datetime.fromisoformat(text)
        except ValueError:
            raise ValueError(f"{name}: {value!r} is not an ISO 8601 date-time with its offset "
                             "(2026-06-21T09:30+02:00)") from None
    if not isinstance(value, _dt.datetime):
        raise TypeError(f"{name}: expected a datetime.datetime with a time zone, or an ISO "
                        f"8601 string, got {type(value).__name__}")
    if value.utcoffset() is None:
        raise ValueError(f"{name}: {value.isoformat()} has no time zone: give one (tzinfo=, "
                         "or an offset such as +02:00 or Z); none is guessed")
    for what in ("local", "UTC"):  # as the command checks both (and year 9999 + 1 fails)
        y = value.year if what == "local" else value.astimezone(_dt.timezone.utc).year
        if not _YEARS[0] <= y <= _YEARS[1]:
            raise ValueError(f"{name}: {value.isoformat()} ({what} year {y}) is outside the "
                             f"years {_YEARS[0]}..{_YEARS[1]}")
    d = value - _EPOCH
    return float(d.days * 86400 + d.seconds) + d.microseconds / 1e6


def _site(lat, lon, elevation, linke, convergence):
    site = ffi.new("hfs_gis_site *")
    site.lat = number("lat", lat, -90.0, 90.0)
    site.lon = number("lon", lon, -360.0, 360.0)
    site.elevation_m = math.nan if elevation is None else number("elevation", elevation,
                                                                 -1000.0, 9000.0)
    site.linke = number("linke", linke, 1.0, 10.0)
    site.convergence_deg = number("convergence", convergence, -180.0, 180.0)
    return site


def sun(dem, cell_size, when, lat, lon, *, elevation=None, linke=3.0, radius=0.0, zscale=1.0,
        nodata=None, backend="gles", renderer=None, method="exact", convergence=0.0):
    """The sun at one instant, as `hfshade sun --datetime WHEN`'s bands 1 and
    2: returns (beam, visible).

    beam: the clear sky's direct-beam irradiance on each texel's tilted,
    terrain-shadowed surface, W/m^2 (ESRA as GRASS r.sun, Linke turbidity
    `linke`, 1..10); visible: the fraction of the sun's disk in view, 0..1
    (0 on a slope facing away).  A sun at or below the horizon gives zeros.
    when: a timezone-aware datetime or an ISO 8601 string with its offset.
    lat, lon: WGS84 degrees of the site the sun is seen from (the command's:
    the centre of the DEM's extent); elevation: its height in metres, None
    = the DEM's centre texel times zscale (the command's).  radius: metres;
    0 or None: shadows from as far as they reach, else none cast from
    farther (`--radius`; refused with the truth).  convergence: degrees, the
    angle from true north to the grid's north (up its columns) at the site,
    positive where grid north lies east of true north (a UTM grid east of
    its central meridian, in the north): the command's
    HFS_GRID_CONVERGENCE_DEG, from the DEM's CRS; 0 (the default) for a
    grid whose up is true north.  Other arguments as svf()."""
    d = _Dem(dem, cell_size, zscale, nodata)
    site = _site(lat, lon, elevation, linke, convergence)
    t = _instant("when", when)
    rad = _radius(radius)
    beam = np.empty(d.shape, dtype=np.float32)
    visible = np.empty(d.shape, dtype=np.float32)

    def go(r):
        err = new_error()
        check(gis_lib().hfs_gis_sun(r, d.c, site, t, rad, ffi.from_buffer("float[]", beam),
                                    ffi.from_buffer("float[]", visible), err), err)
    _run(renderer, backend, go, method)
    return d.masked(beam, _SUN), d.masked(visible, _SUN)


def insolation(dem, cell_size, start, end, lat, lon, *, step=15.0, directions=16, radius=0.0,
               elevation=None, linke=3.0, zscale=1.0, nodata=None, backend="gles",
               renderer=None, sky_map=None, sky_north=0.0, albedo=0.0, method="exact",
               convergence=0.0, beam_only=False):
    """Clear-sky irradiation over [start, end), Wh/m^2, as `hfshade
    insolation --from START --to END`'s bands 1, 2, 3: returns
    (beam, diffuse, global_); with beam_only (`--beam-only`) (beam, None,
    None), the sky's horizons not searched (no sky_map, albedo 0).

    Steps of `step` minutes (default 15; the last one shortened to end at
    `end`; at most 100000), each step's sun at its middle.  beam: the
    direct beam on the tilted, shadowed surface summed over the steps with
    the sun up; diffuse: the diffuse horizontal irradiation times the share
    of an isotropic sky each texel gets under the terrain's horizons in
    `directions` azimuths (1..1024, default 16); global_: their sum.
    radius: metres, also the sky's horizons' search (0 or None: to the
    DEM's edge).  start, end, lat, lon, elevation, linke, convergence as
    sun()'s; other arguments as svf().

    sky_map: the sky's shape instead of an isotropic sky (`--sky-map`): an
    (h, w, 3) linear RGB equirectangular map, row 0 the zenith, its upper
    half finite, >= 0 and not all black; column u looks at compass azimuth
    sky_north + 360 u degrees (`--sky-north`, default 0: true north; the
    grid's convergence turns it onto the grid).  The clear
    sky still gives the diffuse light's amount at each step.  albedo: the
    ground's, 0..1 (`--albedo`); global_ then adds the light the ground and
    the terrain reflect onto the texel (r.sun's refl_rad; 0: none)."""
    d = _Dem(dem, cell_size, zscale, nodata)
    site = _site(lat, lon, elevation, linke, convergence)
    t0, t1 = _instant("start", start), _instant("end", end)
    minutes = number("step", step, 0.0, 1e9)
    if minutes <= 0.0:
        raise ValueError(f"step: {step!r} is not a number of minutes above 0")
    n = integer("directions", directions, 1, 1024)
    rad = _radius(radius)
    sky, north = ffi.NULL, number("sky_north", sky_north, -360.0, 360.0)
    rho = number("albedo", albedo, 0.0, 1.0)
    if sky_map is not None:
        sky_map = env_map_array(sky_map, "sky_map")
        sky = ffi.from_buffer("float[]", sky_map)
    out = [np.empty(d.shape, dtype=np.float32) for _ in range(1 if beam_only else 3)]

    def go(r):
        err = new_error()
        h, w = (sky_map.shape[0], sky_map.shape[1]) if sky_map is not None else (0, 0)
        bufs = [ffi.from_buffer("float[]", o) for o in out] + [ffi.NULL] * (3 - len(out))
        check(gis_lib().hfs_gis_insolation_sky(r, d.c, site, t0, t1, minutes, n, rad, sky, w,
                                               h, north, rho, *bufs, err), err)
    _run(renderer, backend, go, method)
    bands = [d.masked(o, _INSOLATION) for o in out]
    return tuple(bands + [None] * (3 - len(bands)))


__all__ = ["svf", "horizon", "openness", "sun", "insolation"]
