/*
 * gis_lit.c — see gis_lit.h.
 */
#include "gis_lit.h"

#include "geotiff_write.h"
#include "gis_dem.h"
#include "gis_math.h"
#include "gis_raster.h"
#include "gis_resample.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

static const char *const what[3] = {"exit radiance, red (linear)",
                                    "exit radiance, green (linear)",
                                    "exit radiance, blue (linear)"};

/* dem (opened) on its own grid as the lit render is: see the header. */
static int own_grid(const gis_dem *dem, const char *path, hfs_error *err)
{
    if (!dem->wkt[0])
        return hfs_fail(err, HFS_E_INVALID, "%s: no CRS (render tiles are georeferenced parts "
                        "of the DEM's grid)", path);
    if (dem->ex != 1 || dem->ey != 1 || !dem->square)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s (render tiles need the DEM's own grid; "
                        "gdalwarp it first)", path, dem->square ? "rows run north or columns "
                        "west" : "cells not square");
    return HFS_OK;
}

int gis_lit_check_grid(const char *dem_path, const hfs_height_load_opts *opts, hfs_error *err)
{
    gis_dem dem;
    int rc = gis_dem_open(dem_path, opts, &dem, err);
    if (!rc)
        rc = own_grid(&dem, dem_path, err);
    gis_dem_free(&dem);
    return rc;
}

int gis_lit_write_part(hfs_outputs *o, const char *path, const char *dem_path,
                       const hfs_height_load_opts *opts, const hfs_image *part, int ix, int iy,
                       hfs_error *err)
{
    gis_dem dem;
    int rc = gis_dem_open(dem_path, opts, &dem, err);
    if (!rc)
        rc = own_grid(&dem, dem_path, err);
    const int w = part->width, h = part->height;
    const size_t n = (size_t)w * (size_t)h;
    float *planes = rc ? NULL : malloc(4 * n * sizeof *planes);
    unsigned char *hole = rc ? NULL : malloc(n);
    long holes;
    if (!rc && (!planes || !hole))
        rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %dx%d part", path, w, h);
    if (!rc) /* the part's holes: the DEM's, read where the part lies */
        rc = gis_dem_read_window(&dem, dem_path, ix, iy, w, h, planes + 3 * n, hole, &holes,
                                 err);
    if (!rc) {
        const float nodata = gis_nodata_for(dem.has_nodata, dem.nodata, 0.0, FLT_MAX);
        double gt[6];
        memcpy(gt, dem.gt, sizeof gt);
        gt[0] += ix * gt[1] + iy * gt[2];
        gt[3] += ix * gt[4] + iy * gt[5];
        gis_raster g = {.width = w, .height = h, .n_bands = 3, .geotransform = gt,
                        .wkt = dem.wkt, .nodata = nodata, .meta = {"HFS_PRODUCT=render", NULL}};
        for (int c = 0; c < 3; ++c) {
            float *band = planes + (size_t)c * n;
            for (size_t p = 0; p < n; ++p)
                band[p] = hole[p] ? nodata : part->rgb[3 * p + (size_t)c];
            g.band[c] = (gis_band){band, what[c], ""};
        }
        rc = gis_raster_write(o, path, &g, err);
    }
    free(hole);
    free(planes);
    gis_dem_free(&dem);
    return rc;
}

int gis_lit_write(hfs_outputs *o, const char *path, const char *dem_path,
                  const hfs_height_load_opts *opts, const hfs_image *lit,
                  const hfs_heightmap *hm, hfs_error *err)
{
    gis_dem dem;
    hfs_error quiet;
    if (!hm->has_georef || gis_dem_read(dem_path, opts, &dem, &quiet))
        return hfs_gdal_write_geotiff(o, path, lit, hm, err); /* no grid of its own */
    int rc = HFS_OK;
    if (dem.ex != 1 || dem.ey != 1 || dem.sw != lit->width || dem.sh != lit->height) {
        rc = hfs_gdal_write_geotiff(o, path, lit, hm, err);
        goto out;
    }
    const size_t n = (size_t)dem.width * (size_t)dem.height, sn = (size_t)dem.sw * dem.sh;
    float *planes = malloc((3 * n + sn) * sizeof *planes);
    if (!planes) {
        rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %dx%d raster", path,
                      dem.width, dem.height);
        goto out;
    }
    const float nodata = gis_nodata_for(dem.has_nodata, dem.nodata, 0.0, FLT_MAX);
    float *channel = planes + 3 * n;
    gis_raster g = {.width = dem.width, .height = dem.height, .n_bands = 3,
                    .geotransform = dem.gt, .wkt = dem.wkt, .nodata = nodata,
                    .meta = {"HFS_PRODUCT=render", NULL}};
    for (int c = 0; c < 3; ++c) {
        for (size_t p = 0; p < sn; ++p)
            channel[p] = lit->rgb[3 * p + (size_t)c];
        gis_sample_back(channel, dem.sw, dem.sh, dem.cx / dem.d, dem.cy / dem.d, dem.width,
                        dem.height, dem.hole, nodata, planes + (size_t)c * n);
        g.band[c] = (gis_band){planes + (size_t)c * n, what[c], ""};
    }
    rc = gis_raster_write(o, path, &g, err);
    free(planes);
out:
    gis_dem_free(&dem);
    return rc;
}
