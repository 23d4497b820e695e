/*
 * gis_resample.h — a product computed on the square cells the renderer
 * takes, brought back to the input DEM's own grid (issue 39: every GIS
 * raster comes back on the input's grid, texel for texel).
 *
 * The square grid is hfs_gdal_make_square's (tools/gdal/height_gdal.h):
 * node-aligned, cells of d = min(cx, cy), its node (i, j) at the input's
 * point (i d / cx, j d / cy).  So the input's texel (i, j) lies at the
 * square grid's point (i sx, j sy) with sx = cx / d, sy = cy / d; the value
 * there is bilinear between the square grid's four nodes around it (the
 * last node clamped: make_square rounds its size to whole cells).
 * No GDAL, no renderer: tests/test_gis_math.c pins it.
 */
#ifndef HFS_GIS_RESAMPLE_H
#define HFS_GIS_RESAMPLE_H

/* out[j w + i] (w x h, the input's grid) = v (sw x sh, the square grid) at
 * (i sx, j sy); nodata where hole[j w + i] is set (hole NULL: none) or the
 * value is not finite (a NaN of the product: nodata too).  A grid that
 * was square already (sx = sy = 1, the same size) is copied as it is. */
void gis_sample_back(const float *v, int sw, int sh, double sx, double sy, int w, int h,
                     const unsigned char *hole, float nodata, float *out);

#endif /* HFS_GIS_RESAMPLE_H */
