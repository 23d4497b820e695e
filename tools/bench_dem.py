#!/usr/bin/python3
"""An `hfgen` PFM as a Float32 GeoTIFF DEM for the GIS benchmarks
(tools/bench_gis.sh, tools/bench_gis_tiles.sh): UTM 16N (EPSG:32616),
north-up, square cells of CELL metres, its top-left corner at (700000,
4100000), tiled and deflate-compressed.  The PFM's rows are written as they
come (a fractal has no up).  Needs python3-gdal and python3-numpy.
usage: tools/bench_dem.py IN.pfm OUT.tif CELL_METRES"""
import sys

import numpy as np
from osgeo import gdal, osr

gdal.UseExceptions()
src, dst, cell = sys.argv[1], sys.argv[2], float(sys.argv[3])
with open(src, "rb") as f:
    assert f.readline().strip() == b"Pf", src + ": not a grey PFM"
    w, h = (int(v) for v in f.readline().split())
    scale = float(f.readline())
    z = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4").reshape(h, w)
ds = gdal.GetDriverByName("GTiff").Create(dst, w, h, 1, gdal.GDT_Float32,
                                          ["TILED=YES", "COMPRESS=DEFLATE"])
ds.SetGeoTransform((700000.0, cell, 0.0, 4100000.0, 0.0, -cell))
srs = osr.SpatialReference()
srs.ImportFromEPSG(32616)
ds.SetProjection(srs.ExportToWkt())
ds.GetRasterBand(1).WriteArray(z)
ds = None
