"""tools/examples/python/svf_geotiff.py (HFSHADE_EXAMPLE) writes the SVF
GeoTIFF of a GeoTIFF DEM: the same values and nodata as `hfshade svf`,
the DEM's geotransform and CRS."""
import os
import subprocess
import sys
import unittest

import numpy as np

import util

CELL = 30.0


class Example(util.TempDir):
    def test_svf_geotiff(self):
        gdal = util.gdal()
        if gdal is None:
            self.skipTest("osgeo.gdal is not installed (Debian: python3-gdal)")
        from osgeo import osr
        dem = self.path("dem.tif")
        z = util.terrain(40, 52, seed=11) * 5.0
        z[5:8, 9:12] = -32768.0
        ds = gdal.GetDriverByName("GTiff").Create(dem, 52, 40, 1, gdal.GDT_Float32)
        ds.SetGeoTransform((300000.0, CELL, 0.0, 5000000.0, 0.0, -CELL))
        srs = osr.SpatialReference()
        srs.ImportFromEPSG(32633)
        ds.SetProjection(srs.ExportToWkt())
        ds.GetRasterBand(1).SetNoDataValue(-32768.0)
        ds.GetRasterBand(1).WriteArray(z)
        ds = None
        out, ref = self.path("out.tif"), self.path("ref.tif")
        p = subprocess.run([sys.executable, os.environ["HFSHADE_EXAMPLE"], dem, out,
                            "--backend", "cpu", "--radius", "600"], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        util.run_cli("svf", dem, "-o", ref, "--backend", "cpu", "--radius", 600, "--quiet")
        a, b = gdal.Open(out), gdal.Open(ref)
        self.assertEqual(a.GetGeoTransform(), b.GetGeoTransform())
        self.assertTrue(osr.SpatialReference(wkt=a.GetProjection()).IsSame(
            osr.SpatialReference(wkt=b.GetProjection())))
        self.assertEqual(a.GetRasterBand(1).GetNoDataValue(), -32768.0)
        self.assertEqual(a.GetRasterBand(1).GetNoDataValue(), b.GetRasterBand(1).GetNoDataValue())
        va = a.GetRasterBand(1).ReadAsArray()
        self.assertTrue(util.same_bits(va, b.GetRasterBand(1).ReadAsArray()))
        self.assertTrue((va[5:8, 9:12] == -32768.0).all())
        self.assertTrue(((va[va != -32768.0] > 0) & (va[va != -32768.0] <= 1)).all())

    def test_bad_dem(self):
        p = subprocess.run([sys.executable, os.environ["HFSHADE_EXAMPLE"], self.path("no.tif"),
                            self.path("o.tif")], capture_output=True, text=True)
        self.assertNotEqual(p.returncode, 0)
        self.assertNotIn("Segmentation", p.stderr)


if __name__ == "__main__":
    util.main()
