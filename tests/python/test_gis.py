"""hfshade.svf / horizon / openness from numpy equal `hfshade svf |
horizon | openness` on the same DEM, written as a GeoTIFF with
osgeo.gdal, bit for bit (the commands' GeoTIFFs read back with GDAL),
holes included: masked in Python where the DEM has none, the masked cells
holding the command's nodata value."""
import unittest

import numpy as np

import util
import hfshade

CELL = 25.0
NODATA = -9999.0


class Gis(util.TempDir):
    @classmethod
    def setUpClass(cls):
        cls.gdal = util.gdal_or_skip()

    def setUp(self):
        super().setUp()
        z = util.terrain(45, 60, seed=3) * 4.0
        self.holes = np.zeros(z.shape, bool)
        self.holes[10:13, 20:24] = True
        self.holes[0, 5] = self.holes[44, 59] = True
        z[self.holes] = NODATA
        self.z = z
        self.dem = self.path("dem.tif")
        ds = self.gdal.GetDriverByName("GTiff").Create(self.dem, 60, 45, 1,
                                                         self.gdal.GDT_Float32)
        ds.SetGeoTransform((500000.0, CELL, 0.0, 4000000.0, 0.0, -CELL))
        from osgeo import osr
        srs = osr.SpatialReference()
        srs.ImportFromEPSG(32616)
        ds.SetProjection(srs.ExportToWkt())
        band = ds.GetRasterBand(1)
        band.SetNoDataValue(NODATA)
        band.WriteArray(z)
        ds = None

    def read(self, path, band=1):
        ds = self.gdal.Open(path)
        b = ds.GetRasterBand(band)
        return b.ReadAsArray().astype(np.float32), b.GetNoDataValue()

    def same(self, got, path, band=1):
        want, nodata = self.read(path, band)
        self.assertIsInstance(got, np.ma.MaskedArray)
        self.assertEqual(got.dtype, np.float32)
        self.assertTrue(np.array_equal(np.ma.getmaskarray(got), want == np.float32(nodata)),
                        f"{path}: mask differs from the command's nodata cells")
        self.assertTrue(np.ma.getmaskarray(got)[self.holes].all(), "a hole is not masked")
        self.assertEqual(float(got.fill_value), nodata)
        self.assertTrue(np.isfinite(got.data).all())
        self.assertTrue(util.same_bits(got.filled(), want),
                        f"{path}: max |python - cli| = {np.abs(got.filled() - want).max()}")

    def test_svf_cpu(self):
        util.run_cli("svf", self.dem, "-o", self.path("svf.tif"), "--backend", "cpu", "--quiet")
        self.same(hfshade.svf(self.z, CELL, nodata=NODATA, backend="cpu"), self.path("svf.tif"))

    def test_svf_lambertian_radius_masked_input(self):
        util.run_cli("svf", self.dem, "-o", self.path("l.tif"), "--backend", "cpu", "--quiet",
                     "--lambertian", "--directions", 8, "--radius", 300, "--zscale", 1.5)
        masked = np.ma.MaskedArray(self.z, mask=self.holes)
        got = hfshade.svf(masked, CELL, directions=8, radius=300, kind="lambertian",
                          zscale=1.5, backend="cpu")
        # no nodata value given: the masked cells hold -9999, the command's too
        self.same(got, self.path("l.tif"))
        nan = np.where(self.holes, np.nan, self.z)
        again = hfshade.svf(nan, CELL, directions=8, radius=300, kind="lambertian",
                            zscale=1.5, backend="cpu")
        self.assertTrue(util.same_bits(again.filled(), got.filled()))

    def test_svf_gles(self):
        if not util.gles_available():
            self.skipTest("no GLES context on this machine")
        util.run_cli("svf", self.dem, "-o", self.path("g.tif"), "--quiet")
        self.same(hfshade.svf(self.z, CELL, nodata=NODATA), self.path("g.tif"))

    def test_horizon_both_conventions(self):
        util.run_cli("horizon", self.dem, "-o", self.path("hor"), "--azimuths", "30,200",
                     "--backend", "cpu", "--quiet")
        got = hfshade.horizon(self.z, CELL, [30, 200], nodata=NODATA, backend="cpu")
        self.assertEqual(got.shape, (2, 45, 60))
        self.same(got[0], self.path("hor_030.tif"))
        self.same(got[1], self.path("hor_200.tif"))
        util.run_cli("horizon", self.dem, "-o", self.path("c"), "--azimuths", "45",
                     "--convention", "compass", "--radius", 400, "--backend", "cpu", "--quiet")
        one = hfshade.horizon(self.z, CELL, 45, convention="compass", radius=400,
                              nodata=NODATA, backend="cpu")
        self.same(one, self.path("c_045.tif"))

    def test_openness_default_radius(self):
        util.run_cli("openness", self.dem, "-o", self.path("o.tif"), "--backend", "cpu",
                     "--quiet")
        with hfshade.Renderer("cpu") as r:
            pos, neg = hfshade.openness(self.z, CELL, nodata=NODATA, renderer=r)
        self.same(pos, self.path("o.tif"), 1)
        self.same(neg, self.path("o.tif"), 2)

    def test_sweep(self):
        util.run_cli("svf", self.dem, "-o", self.path("s.tif"), "--method", "sweep", "--quiet")
        self.same(hfshade.svf(self.z, CELL, nodata=NODATA, method="sweep"), self.path("s.tif"))
        util.run_cli("horizon", self.dem, "-o", self.path("sh"), "--azimuths", "30",
                     "--method", "sweep", "--quiet")
        self.same(hfshade.horizon(self.z, CELL, 30, nodata=NODATA, method="sweep"),
                  self.path("sh_030.tif"))
        with self.assertRaisesRegex(ValueError, "^method: 'fast'"):
            hfshade.svf(self.z, CELL, method="fast")
        with self.assertRaisesRegex(ValueError, "^method: 'sweep' takes no renderer"):
            with hfshade.Renderer("cpu") as r:
                hfshade.svf(self.z, CELL, renderer=r, method="sweep")
        with self.assertRaisesRegex(hfshade.Error, "^radius: the sweep .*openness"):
            hfshade.openness(self.z, CELL, method="sweep")
        with self.assertRaisesRegex(hfshade.Error, "^radius: the sweep"):
            hfshade.svf(self.z, CELL, radius=300, method="sweep")

    def test_bad_arguments(self):
        with self.assertRaisesRegex(ValueError, "^cell_size: .*not square"):
            hfshade.svf(self.z, (25.0, 30.0), backend="cpu")
        with self.assertRaisesRegex(ValueError, "^kind: "):
            hfshade.svf(self.z, CELL, kind="sky", backend="cpu")
        with self.assertRaisesRegex(ValueError, "^directions: "):
            hfshade.svf(self.z, CELL, directions=0, backend="cpu")
        with self.assertRaisesRegex(ValueError, "^dem: expected a 2-D array"):
            hfshade.openness(self.z[0], CELL, backend="cpu")
        with self.assertRaisesRegex(hfshade.Error, "^dem: no valid heights") as e:
            hfshade.svf(np.full((4, 4), np.nan), CELL, backend="cpu")
        self.assertEqual(e.exception.status, "format")


if __name__ == "__main__":
    util.main()
