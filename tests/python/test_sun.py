"""hfshade.sun / insolation from numpy equal `hfshade sun | insolation` on
the same DEM, written as a UTM GeoTIFF with osgeo.gdal, bit for bit (every
band of the commands' GeoTIFFs read back with GDAL), holes included: masked
in Python exactly where the DEM has none.  The site is the one the
commands take: the centre of the DEM's extent in WGS84 through OSR
(tools/gis/gis_dem.c gis_dem_lonlat; checked against their HFS_SITE_LON
and HFS_SITE_LAT), its height the centre texel's, here a filled hole.
The instants reach the library as POSIX seconds: their Julian days must be
the command parser's, bit for bit (python_julian_day prints those)."""
import datetime as dt
import math
import os
import subprocess
import unittest

import numpy as np

import util
import hfshade
from hfshade._ffi import ffi, gis_lib

CELL = 30.0
# A nodata value the sun's products could take (>= 0): the commands write
# -9999 instead, and so must the module.
NODATA = 5.0
H, W = 36, 48
GT = (500000.0, CELL, 0.0, 4000000.0, 0.0, -CELL)  # UTM 16N, Tennessee
LOW = "2026-06-21T06:30-05:00"  # the sun about 10 degrees up: long shadows
HOURS = ("2026-06-21T05:30-05:00", "2026-06-21T09:00-05:00")  # 4 steps of 60 min


class Sun(util.TempDir):
    @classmethod
    def setUpClass(cls):
        cls.gdal = util.gdal_or_skip()
        from osgeo import osr
        cls.osr = osr

    def setUp(self):
        super().setUp()
        z = util.terrain(H, W, seed=5) * 8.0 + 300.0  # hills of some 100 m
        self.holes = np.zeros(z.shape, bool)
        self.holes[H // 2 - 1:H // 2 + 2, W // 2 - 1:W // 2 + 1] = True  # the site's texel
        self.holes[0, 3] = self.holes[H - 1, W - 1] = True
        z[self.holes] = NODATA
        self.z = z
        self.dem = self.path("dem.tif")
        srs = self.osr.SpatialReference()
        srs.ImportFromEPSG(32616)
        ds = self.gdal.GetDriverByName("GTiff").Create(self.dem, W, H, 1,
                                                         self.gdal.GDT_Float32)
        ds.SetGeoTransform(GT)
        ds.SetProjection(srs.ExportToWkt())
        band = ds.GetRasterBand(1)
        band.SetNoDataValue(NODATA)
        band.WriteArray(z)
        ds = None
        self.lon, self.lat = self.site(srs)
        self.conv = self.convergence(srs)

    def site(self, srs):
        """gis_dem_lonlat: the extent's centre (0.5 width, 0.5 height) to
        WGS84, traditional GIS axis order, the longitude in (-180, 180]."""
        osr = self.osr
        x = GT[0] + GT[1] * 0.5 * W + GT[2] * 0.5 * H
        y = GT[3] + GT[4] * 0.5 * W + GT[5] * 0.5 * H
        wgs = osr.SpatialReference()
        wgs.SetWellKnownGeogCS("WGS84")
        srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
        wgs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
        lon, lat, _ = osr.CoordinateTransformation(srs, wgs).TransformPoint(x, y)
        return math.remainder(lon, 360.0), lat

    def convergence(self, srs):
        """gis_dem_lonlat's grid convergence, as it computes it: the meridian
        0.001 degrees either side of the centre carried back into the
        DEM's pixels (square 30 m cells, north-up), its angle from the
        grid's up axis."""
        osr = self.osr
        wgs = osr.SpatialReference()
        wgs.SetWellKnownGeogCS("WGS84")
        wgs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
        back = osr.CoordinateTransformation(wgs, srs)
        dlat = min(1e-3, 90.0 - abs(self.lat))
        inv = self.gdal.InvGeoTransform(GT)
        px = []
        for lat in (self.lat - dlat, self.lat + dlat):
            x, y, _ = back.TransformPoint(self.lon, lat)
            px.append(self.gdal.ApplyGeoTransform(inv, x, y))
        east = (px[1][0] - px[0][0]) * CELL
        north = -(px[1][1] - px[0][1]) * CELL
        d = -math.atan2(east, north) * (180.0 / 3.14159265358979323846)
        return 0.0 if abs(d) < 1e-9 else d

    def same(self, got, path, band):
        ds = self.gdal.Open(path)
        b = ds.GetRasterBand(band)
        want, nodata = b.ReadAsArray().astype(np.float32), b.GetNoDataValue()
        self.assertEqual(nodata, -9999.0)
        self.assertIsInstance(got, np.ma.MaskedArray)
        self.assertEqual(got.dtype, np.float32)
        self.assertTrue(np.array_equal(np.ma.getmaskarray(got), self.holes),
                        f"{path} band {band}: the mask is not the DEM's holes")
        self.assertTrue(np.array_equal(want == np.float32(nodata), self.holes))
        self.assertEqual(float(got.fill_value), nodata)
        self.assertTrue(util.same_bits(got.filled(), want),
                        f"{path} band {band}: max |python - cli| = "
                        f"{np.abs(got.filled() - want).max()}")
        return ds.GetMetadata()

    def sun_both(self, backend):
        out = self.path(f"sun_{backend}.tif")
        util.run_cli("sun", self.dem, "-o", out, "--datetime", LOW, "--backend", backend,
                     "--quiet")
        beam, vis = hfshade.sun(self.z, CELL, LOW, self.lat, self.lon, nodata=NODATA,
                                backend=backend, convergence=self.conv)
        meta = self.same(beam, out, 1)
        self.same(vis, out, 2)
        self.assertEqual(meta["HFS_SITE_LON"], f"{self.lon:.6f}")
        self.assertEqual(meta["HFS_SITE_LAT"], f"{self.lat:.6f}")
        self.assertEqual(meta["HFS_GRID_CONVERGENCE_DEG"], f"{self.conv:.6f}")
        self.assertGreater(self.conv, 0.004)  # east of the central meridian
        # not vacuous: a low sun, cast shadows, partial disks and lit slopes
        self.assertLess(float(meta["HFS_SUN_ELEVATION"]), 15.0)
        v = vis.compressed()
        self.assertGreater(int(np.sum(v < 0.5)), 20)
        self.assertGreater(int(np.sum((v > 0.0) & (v < 1.0))), 0)
        self.assertGreater(int(np.sum(beam.compressed() > 100.0)), 100)

    def test_sun_cpu(self):
        self.sun_both("cpu")

    def test_sun_gles(self):
        if not util.gles_available():
            self.skipTest("no GLES context on this machine")
        self.sun_both("gles")

    def test_sun_radius_linke_zscale_masked_input(self):
        out = self.path("r.tif")
        util.run_cli("sun", self.dem, "-o", out, "--datetime", "2026-06-21T06:30:00",
                     "--timezone", "-05:00", "--radius", 100, "--linke", 4.5, "--zscale", 1.5,
                     "--backend", "cpu", "--quiet")
        when = dt.datetime(2026, 6, 21, 6, 30, tzinfo=dt.timezone(dt.timedelta(hours=-5)))
        masked = np.ma.MaskedArray(self.z, mask=self.holes)
        with hfshade.Renderer("cpu") as r:
            beam, vis = hfshade.sun(masked, CELL, when, self.lat, self.lon, radius=100,
                                    linke=4.5, zscale=1.5, renderer=r, convergence=self.conv)
            _, far = hfshade.sun(masked, CELL, when, self.lat, self.lon, linke=4.5,
                                 zscale=1.5, renderer=r, convergence=self.conv)
        self.same(beam, out, 1)
        self.same(vis, out, 2)
        self.assertGreater(int(np.sum(vis != far)), 0, "the radius cut no shadow")
        high, _ = hfshade.sun(masked, CELL, when, self.lat, self.lon, radius=100, linke=4.5,
                              zscale=1.5, elevation=2500.0, backend="cpu",
                              convergence=self.conv)
        # a site higher up: thinner air, more beam (and less refraction)
        self.assertGreater(float(high.mean()), 1.1 * float(beam.mean()))

    def test_sun_below_the_horizon(self):
        out = self.path("night.tif")
        util.run_cli("sun", self.dem, "-o", out, "--datetime", "2026-06-21T00:00-05:00",
                     "--backend", "cpu", "--quiet")
        beam, vis = hfshade.sun(self.z, CELL, "2026-06-21T05:00Z", self.lat, self.lon,
                                nodata=NODATA, backend="cpu", convergence=self.conv)
        self.same(beam, out, 1)
        self.same(vis, out, 2)
        self.assertEqual(float(np.abs(beam).sum() + np.abs(vis).sum()), 0.0)

    def insolation_both(self, backend, *extra, **kwargs):
        out = self.path(f"ins_{backend}.tif")
        util.run_cli("insolation", self.dem, "-o", out, "--from", HOURS[0], "--to", HOURS[1],
                     "--step", 60, "--directions", 8, "--backend", backend, "--quiet", *extra)
        with hfshade.Renderer(backend) as r:
            bands = hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, step=60,
                                       directions=8, nodata=NODATA, renderer=r,
                                       convergence=self.conv, **kwargs)
        self.assertEqual(len(bands), 3)
        for k, b in enumerate(bands):
            meta = self.same(b, out, k + 1)
        self.assertEqual(meta["HFS_STEPS"], "4")
        self.assertEqual(meta["HFS_STEPS_SUN"], "4")
        beam, diffuse, total = (b.compressed() for b in bands)
        self.assertGreater(float(beam.max()), 500.0)
        self.assertGreater(float(diffuse.min()), 0.0)
        self.assertLess(float(diffuse.min()), float(diffuse.max()))

    def test_insolation_cpu(self):
        self.insolation_both("cpu")

    def test_insolation_gles_radius(self):
        if not util.gles_available():
            self.skipTest("no GLES context on this machine")
        self.insolation_both("gles", "--radius", 200, "--linke", 2, radius=200, linke=2)

    def test_insolation_sky_map(self):
        # a sky bright towards the north-east, as a file for the command (PFM,
        # top row first) and as an array for the module: the same bits
        h, w = 16, 32
        compass = 360.0 * (np.arange(w) + 0.5) / w
        glow = 1.0 + 4.0 * np.maximum(0.0, np.cos(np.radians(compass - 45.0)))
        sky = np.repeat((np.ones((h, 1)) * glow)[:, :, None], 3, axis=2).astype(np.float32)
        sky[:, :, 2] *= 0.5
        pfm = self.path("sky.pfm")
        with open(pfm, "wb") as f:
            f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
            f.write(sky.astype("<f4").tobytes())
        out = self.path("ins_sky.tif")
        util.run_cli("insolation", self.dem, "-o", out, "--from", HOURS[0], "--to", HOURS[1],
                     "--step", 60, "--directions", 8, "--backend", "cpu", "--quiet",
                     "--sky-map", pfm, "--sky-north", 30, "--albedo", 0.25)
        bands = hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, step=60,
                                   directions=8, nodata=NODATA, backend="cpu", sky_map=sky,
                                   sky_north=30, albedo=0.25, convergence=self.conv)
        for k, b in enumerate(bands):
            meta = self.same(b, out, k + 1)
        self.assertEqual(meta["HFS_SKY_MAP"], "sky.pfm")
        self.assertEqual(meta["HFS_ALBEDO"], "0.25")
        iso = hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, step=60,
                                 directions=8, nodata=NODATA, backend="cpu",
                                 convergence=self.conv)
        self.assertEqual(iso[0].tobytes(), bands[0].tobytes())  # the beam is the sun's
        self.assertGreater(float(np.abs(iso[1] - bands[1]).max()), 0.0)
        with self.assertRaisesRegex(hfshade.Error, "sky: pixel .* negative"):
            hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, step=60,
                               backend="cpu", sky_map=-sky)
        with self.assertRaisesRegex(ValueError, "^albedo: "):
            hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, backend="cpu",
                               albedo=1.5)
        with self.assertRaisesRegex(ValueError, "^sky_north: "):
            hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, backend="cpu",
                               sky_map=sky, sky_north=400)
        with self.assertRaisesRegex(ValueError, "^sky_map: expected an .h, w, 3. RGB map"):
            hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, backend="cpu",
                               sky_map=sky[:, :, :2])

    def test_insolation_beam_only(self):
        # --beam-only: one band, the full run's band 1 bit for bit
        out = self.path("ins_beam.tif")
        util.run_cli("insolation", self.dem, "-o", out, "--from", HOURS[0], "--to", HOURS[1],
                     "--step", 60, "--backend", "cpu", "--quiet", "--beam-only")
        beam, diffuse, total = hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon,
                                                  step=60, nodata=NODATA, backend="cpu",
                                                  convergence=self.conv, beam_only=True)
        self.assertIsNone(diffuse)
        self.assertIsNone(total)
        meta = self.same(beam, out, 1)
        self.assertEqual(meta["HFS_BANDS"], "beam")
        full = hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, step=60,
                                  nodata=NODATA, backend="cpu", convergence=self.conv)
        self.assertEqual(full[0].tobytes(), beam.tobytes())
        with self.assertRaisesRegex(hfshade.Error, "beam alone takes no sky map and no albedo"):
            hfshade.insolation(self.z, CELL, *HOURS, self.lat, self.lon, backend="cpu",
                               albedo=0.2, beam_only=True)

    def test_julian_day_is_the_commands(self):
        instants = ["2026-06-21T06:30-05:00", "2026-12-31T23:59:59-03:30", "2024-02-29T12:00Z",
                    "2000-01-01T12:00:00Z", "1969-12-31T23:59:59+00:00", "1900-03-01T00:30+01:00",
                    "1955-07-04T18:07:43-07:00", "2100-12-31T23:59:59Z", "2026-03-01T00:00+14:00"]
        p = subprocess.run([os.environ["HFSHADE_JULIAN_DAY"], *instants], capture_output=True,
                           text=True, check=True)
        lines = p.stdout.splitlines()
        self.assertEqual(len(lines), len(instants))
        for text, line in zip(instants, lines):
            name, hexa = line.split()
            self.assertEqual(name, text)
            for value in (text, dt.datetime.fromisoformat(text.replace("Z", "+00:00"))):
                t = hfshade.gis._instant("when", value)
                jd, err = ffi.new("double *"), ffi.new("hfs_error *")
                self.assertEqual(gis_lib().hfs_gis_julian_day(t, jd, err), 0)
                self.assertEqual(jd[0].hex(), float.fromhex(hexa).hex(), text)

    def test_bad_arguments(self):
        z, la, lo = self.z, self.lat, self.lon
        naive = dt.datetime(2026, 6, 21, 6, 30)
        with self.assertRaisesRegex(ValueError, "^when: .*has no time zone"):
            hfshade.sun(z, CELL, naive, la, lo, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^start: .*has no time zone"):
            hfshade.insolation(z, CELL, "2026-06-21T06:30", HOURS[1], la, lo, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^when: 'dawn' is not an ISO 8601"):
            hfshade.sun(z, CELL, "dawn", la, lo, backend="cpu")
        with self.assertRaisesRegex(TypeError, "^when: expected a datetime"):
            hfshade.sun(z, CELL, 1750000000, la, lo, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^end: .*outside the years 1900..2100"):
            hfshade.insolation(z, CELL, HOURS[0], "2101-01-01T00:00Z", la, lo, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^lat: "):
            hfshade.sun(z, CELL, LOW, 91, lo, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^linke: "):
            hfshade.sun(z, CELL, LOW, la, lo, linke=0.5, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^elevation: "):
            hfshade.sun(z, CELL, LOW, la, lo, elevation=9500, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^convergence: "):
            hfshade.sun(z, CELL, LOW, la, lo, convergence=200, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^step: "):
            hfshade.insolation(z, CELL, *HOURS, la, lo, step=0, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^directions: "):
            hfshade.insolation(z, CELL, *HOURS, la, lo, directions=1025, backend="cpu")
        # the library's own checks, with the command's rules
        with self.assertRaisesRegex(hfshade.Error, r"^end: .* is not after start"):
            hfshade.insolation(z, CELL, HOURS[1], HOURS[0], la, lo, backend="cpu")
        with self.assertRaisesRegex(hfshade.Error, r"^step: 0.001 minutes over 210 minutes "
                                    r"makes 210000 steps \(at most 100000\)"):
            hfshade.insolation(z, CELL, *HOURS, la, lo, step=0.001, backend="cpu")
        with self.assertRaisesRegex(hfshade.Error, "^radius: not with the truth"):
            hfshade.sun(z, CELL, LOW, la, lo, radius=100, backend="truth")
        with self.assertRaisesRegex(hfshade.Error, r"^dem: the height at its centre, 1\d{4}"):
            hfshade.sun(z, CELL, LOW, la, lo, zscale=40, nodata=NODATA, backend="cpu")
        self.c_checks()

    def c_checks(self):
        """What Python checks first, the library checks too (C callers)."""
        lib, err = gis_lib(), ffi.new("hfs_error *")
        jd = ffi.new("double *")
        self.assertNotEqual(lib.hfs_gis_julian_day(-2208988801.0, jd, err), 0)  # 1899
        self.assertRegex(ffi.string(err.msg).decode(), "^unix_utc: .*years 1900..2100")
        self.assertEqual(lib.hfs_gis_julian_day(-2208988800.0, jd, err), 0)
        self.assertEqual(jd[0], 2415020.5)  # 1900-01-01T00:00Z
        self.assertNotEqual(lib.hfs_gis_julian_day(math.nan, jd, err), 0)
        d = hfshade.gis._Dem(self.z, CELL, 1.0, NODATA)
        out = [np.empty((H, W), np.float32) for _ in range(3)]
        buf = [ffi.from_buffer("float[]", o) for o in out]
        t = hfshade.gis._instant("when", LOW)
        cases = [((math.nan, 0.0, math.nan, 0.0), "^lat: nan is not a latitude"),
                 ((0.0, 361.0, math.nan, 0.0), "^lon: 361 is not a longitude"),
                 ((0.0, 0.0, -1001.0, 0.0), "^elevation: -1001 m"),
                 ((0.0, 0.0, math.nan, 10.5), "^linke: 10.5 is not a Linke turbidity"),
                 ((0.0, 0.0, math.nan, 0.0, 181.0), "^convergence: 181 is not an angle")]
        with hfshade.Renderer("cpu") as r:
            for fields, message in cases:
                site = ffi.new("hfs_gis_site *", fields)
                self.assertNotEqual(lib.hfs_gis_sun(r.handle, d.c, site, t, 0.0, buf[0], buf[1],
                                                    err), 0)
                self.assertRegex(ffi.string(err.msg).decode(), message)
            self.assertNotEqual(lib.hfs_gis_sun(r.handle, d.c, ffi.NULL, t, 0.0, buf[0], buf[1],
                                                err), 0)
            self.assertRegex(ffi.string(err.msg).decode(), "^site: none given")
            site = ffi.new("hfs_gis_site *", (self.lat, self.lon, math.nan, 0.0, self.conv))
            self.assertNotEqual(lib.hfs_gis_insolation(r.handle, d.c, site, t, t + 3600, 15.0,
                                                       0, 0.0, *buf, err), 0)
            self.assertRegex(ffi.string(err.msg).decode(), "^directions: 0 ")
            # linke 0: r.sun's 3.0, the command's default
            self.assertEqual(lib.hfs_gis_sun(r.handle, d.c, site, t, 0.0, buf[0], buf[1], err), 0)
            beam, _ = hfshade.sun(self.z, CELL, LOW, self.lat, self.lon, nodata=NODATA,
                                  renderer=r, convergence=self.conv)
        self.assertTrue(util.same_bits(out[0], beam.filled()))


if __name__ == "__main__":
    util.main()
