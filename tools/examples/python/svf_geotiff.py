#!/usr/bin/python3
"""svf_geotiff.py DEM.tif OUT.tif [--directions N] [--radius M] [--backend B]

The sky-view factor of a GeoTIFF DEM with the hfshade Python module:
the DEM read with GDAL (osgeo.gdal, Debian's python3-gdal) as a masked
array, its cells' size from its geotransform, the SVF written as a Float32
GeoTIFF on the DEM's grid with its georeferencing and a nodata value
(what `hfshade svf DEM.tif -o OUT.tif` writes, value for value).

The DEM must be north-up with square cells in metres (a projected CRS):
reproject others first, e.g. `gdalwarp -t_srs EPSG:32633 -tr 30 30`.
"""
import argparse
import sys

import numpy as np
from osgeo import gdal, osr

import hfshade


def read_dem(path):
    ds = gdal.Open(path)
    gt = ds.GetGeoTransform()
    if gt[2] != 0.0 or gt[4] != 0.0 or gt[1] <= 0.0 or gt[5] >= 0.0:
        sys.exit(f"{path}: not a north-up raster (geotransform {gt}); gdalwarp it first")
    srs = osr.SpatialReference(wkt=ds.GetProjection()) if ds.GetProjection() else None
    if srs is not None and srs.IsGeographic():
        sys.exit(f"{path}: cells in degrees; reproject to metres first (gdalwarp -t_srs ...)")
    band = ds.GetRasterBand(1)
    z = band.ReadAsArray().astype(np.float32)
    nodata = band.GetNoDataValue()
    mask = ~np.isfinite(z) if nodata is None else (z == np.float32(nodata)) | ~np.isfinite(z)
    return np.ma.MaskedArray(z, mask=mask), (gt[1], gt[5]), ds.GetProjection(), gt, nodata


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[2])
    p.add_argument("dem")
    p.add_argument("out")
    p.add_argument("--directions", type=int, default=16)
    p.add_argument("--radius", type=float, default=None, help="metres (default: whole DEM)")
    p.add_argument("--backend", default="gles", choices=("gles", "cpu", "truth"))
    a = p.parse_args()
    gdal.UseExceptions()
    dem, cell, wkt, gt, nodata = read_dem(a.dem)
    try:
        svf = hfshade.svf(dem, cell, directions=a.directions, radius=a.radius,
                          nodata=nodata, backend=a.backend)
    except (hfshade.Error, ValueError) as e:
        sys.exit(f"{a.dem}: {e}")
    out = gdal.GetDriverByName("GTiff").Create(a.out, dem.shape[1], dem.shape[0], 1,
                                               gdal.GDT_Float32)
    out.SetGeoTransform(gt)
    out.SetProjection(wkt)
    band = out.GetRasterBand(1)
    band.SetNoDataValue(float(svf.fill_value))
    band.WriteArray(svf.filled())
    out = None
    print(f"{a.out}: sky-view factor of {dem.shape[1]}x{dem.shape[0]}, "
          f"{int(np.ma.count_masked(svf))} nodata texels", file=sys.stderr)


if __name__ == "__main__":
    main()
