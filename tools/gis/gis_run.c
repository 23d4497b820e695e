/*
 * gis_run.c — see gis_run.h: what every product's writer takes from the
 * run (its metadata items, a raster of the input's grid).
 */
#include "gis_run.h"

#include <stdarg.h>
#include <stdio.h>

void gis_run_meta(gis_run *r, const char *fmt, ...)
{
    if (r->n_meta == (int)(sizeof r->meta / sizeof r->meta[0]))
        return; /* a programming error: the tests read every item they set */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->meta[r->n_meta++], GIS_RUN_META_LEN, fmt, ap);
    va_end(ap);
}

gis_raster gis_run_raster(const gis_run *r, const char *extra)
{
    gis_raster g = {.width = r->dem.width, .height = r->dem.height, .n_bands = 1,
                    .geotransform = r->dem.gt, .wkt = r->dem.wkt, .nodata = r->c.nodata,
                    .cog = r->a->cog};
    int k = 0;
    for (; k < r->n_meta; ++k)
        g.meta[k] = r->meta[k];
    g.meta[k] = extra;
    return g;
}
