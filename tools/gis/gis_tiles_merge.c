/*
 * gis_tiles_merge.c — `hfshade tiles merge` (gis_tiles.h): GDAL's
 * GDALBuildVRT over the jobs' GeoTIFFs (no pixel copied, no resampling:
 * the tiles are parts of one grid), the first tile's metadata and band
 * descriptions carried onto it, then GDALCreateCopy into a temporary of
 * the run's outputs (gis_outputs.h) renamed into place with the others.
 */
#include "gis_tiles.h"

#include "gdal_lazy.h"
#include "gis_outputs.h"
#include "gis_raster.h"

#include <cpl_string.h>
#include <gdal.h>
#include <gdal_utils.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MISSING_NAMED 8 /* missing jobs named in the one line */

/* The jobs with a file of suffix s missing: 0, or an error naming them. */
static int check_tiles(const gis_tiles_plan_t *m, int s, hfs_error *err)
{
    char p[PATH_MAX + 64], list[160] = "";
    int missing = 0, first = 0;
    for (int k = 1; k <= m->jobs; ++k) {
        if (gis_tiles_path(m, k, s, p, sizeof p) == 0 && access(p, F_OK) == 0)
            continue;
        first = first ? first : k;
        if (++missing <= MISSING_NAMED) {
            const size_t used = strlen(list);
            snprintf(list + used, sizeof list - used, "%s%d", used ? ", " : "", k);
        }
    }
    if (!missing)
        return HFS_OK;
    return hfs_fail(err, HFS_E_INVALID, "%s/manifest: %d of %d jobs have no tiles/N%s: %s%s "
                    "(hfshade tiles run %s/manifest %d)", m->dir, missing, m->jobs, m->suffix[s],
                    list, missing > MISSING_NAMED ? ", ..." : "", m->dir, first);
}

/* The first tile's metadata and band descriptions, units and nodata onto
 * the VRT (GDALBuildVRT keeps only the nodata); 1 when the tile is plain
 * (no predictor: gis_raster.h), so that the mosaic is written as its
 * tiles were. */
static int describe_like(GDALDatasetH vrt, const char *tile)
{
    GDALDatasetH t = GDALOpen(tile, GA_ReadOnly);
    if (!t)
        return 0;
    /* the tiles' own encoding: plain where they have no predictor */
    const char *pred = GDALGetMetadataItem(t, "PREDICTOR", "IMAGE_STRUCTURE");
    const int plain = !pred || !strcmp(pred, "1");
    GDALSetMetadata(vrt, GDALGetMetadata(t, NULL), NULL);
    for (int b = 1; b <= GDALGetRasterCount(t) && b <= GDALGetRasterCount(vrt); ++b) {
        GDALRasterBandH from = GDALGetRasterBand(t, b), to = GDALGetRasterBand(vrt, b);
        GDALSetDescription(to, GDALGetDescription(from));
        GDALSetRasterUnitType(to, GDALGetRasterUnitType(from));
    }
    GDALClose(t);
    return plain;
}

/* Output s: the VRT of its tiles in the plan's directory, copied to tmp
 * (named path in messages). */
static int merge_one(const gis_tiles_plan_t *m, int s, const char *path, const char *tmp,
                     int cog, hfs_error *err)
{
    char **names = calloc((size_t)m->jobs + 1, sizeof *names), vrt[PATH_MAX + 64];
    int rc = names ? HFS_OK : hfs_fail(err, HFS_E_NOMEM, "tiles merge: out of memory");
    for (int k = 0; k < m->jobs && !rc; ++k) {
        char p[PATH_MAX + 64];
        if (gis_tiles_path(m, k + 1, s, p, sizeof p) || !(names[k] = strdup(p)))
            rc = hfs_fail(err, HFS_E_NOMEM, "tiles merge: out of memory");
    }
    const size_t n = strlen(m->suffix[s]);
    snprintf(vrt, sizeof vrt, "%s/mosaic%.*s.vrt", m->dir, (int)(n > 4 ? n - 4 : 0), m->suffix[s]);
    GDALDatasetH v = NULL, o = NULL;
    if (!rc) {
        int usage = 0;
        v = GDALBuildVRT(vrt, m->jobs, NULL, (const char *const *)names, NULL, &usage);
        if (!v)
            rc = hfs_fail(err, HFS_E_IO, "%s: GDAL could not build the mosaic: %s", vrt,
                          CPLGetLastErrorMsg());
    }
    if (!rc) {
        const int plain = describe_like(v, names[0]); /* as the tiles were written */
        char **opts = gis_raster_options(cog, plain);
        o = GDALCreateCopy(GDALGetDriverByName(cog ? "COG" : "GTiff"), tmp, v, FALSE, opts,
                           NULL, NULL);
        CSLDestroy(opts);
        if (!o)
            rc = hfs_fail(err, HFS_E_IO, "%s: GDAL could not write it: %s", path,
                          CPLGetLastErrorMsg());
    }
    if (o) { /* GDALClose is void before GDAL 3.8: its errors are the last error */
        CPLErrorReset();
        GDALClose(o);
        if (CPLGetLastErrorType() >= CE_Failure && !rc)
            rc = hfs_fail(err, HFS_E_IO, "%s: GDAL could not finish it: %s", path,
                          CPLGetLastErrorMsg());
    }
    if (v)
        GDALClose(v);
    for (int k = 0; names && k < m->jobs; ++k)
        free(names[k]);
    free(names);
    return rc;
}

int gis_tiles_merge(const gis_tiles_plan_t *m, const char *out, int cog, hfs_error *err)
{
    const int horizon = !strcmp(m->product, "horizon");
    char **paths = calloc((size_t)m->n_suffix, sizeof *paths);
    gis_outputs *outs = NULL;
    int rc = hfs_gdal_need(out, err);
    if (!rc)
        rc = paths ? gis_outputs_create(&outs, m->dem, m->n_suffix, err)
                   : hfs_fail(err, HFS_E_NOMEM, "tiles merge: out of memory");
    /* horizon: out is a PREFIX, with or without .tif (as the command's -o) */
    const size_t len = strlen(out);
    const int keep = horizon && len > 4 && !strcmp(out + len - 4, ".tif") ? (int)len - 4
                                                                           : (int)len;
    for (int s = 0; s < m->n_suffix && !rc; ++s) {
        const size_t n = len + strlen(m->suffix[s]) + 1;
        if (!(paths[s] = malloc(n)))
            rc = hfs_fail(err, HFS_E_NOMEM, "tiles merge: out of memory");
        else
            snprintf(paths[s], n, "%.*s%s", keep, out, horizon ? m->suffix[s] : "");
        if (!rc)
            rc = check_tiles(m, s, err);
        if (!rc)
            rc = gis_outputs_add(outs, paths[s], err);
    }
    for (int s = 0; s < m->n_suffix && !rc; ++s) {
        const char *tmp = NULL;
        rc = gis_outputs_temporary(outs, paths[s], &tmp, err);
        if (!rc)
            rc = merge_one(m, s, paths[s], tmp, cog, err);
    }
    if (!rc)
        rc = gis_outputs_commit(outs, err);
    gis_outputs_destroy(outs);
    for (int s = 0; paths && s < m->n_suffix; ++s)
        free(paths[s]);
    free(paths);
    return rc;
}
