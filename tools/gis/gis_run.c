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

int gis_run_bands(const gis_run *r)
{
    const gis_product p = r->a->product;
    if (p == GIS_INSOLATION)
        return r->a->beam_only ? 1 : 3;
    return p == GIS_OPENNESS || p == GIS_SUN ? 2 : 1;
}

gis_raster gis_run_product_raster(const gis_run *r, const float *v, size_t n)
{
    gis_raster g = gis_run_raster(r, NULL);
    if (r->a->product == GIS_SVF) {
        g.band[0] = (gis_band){v, r->a->svf == GIS_SVF_LAMBERTIAN
                                      ? "sky-view factor, Lambertian (Haentzschel et al. 2005)"
                                      : "sky-view factor (Zaksek et al. 2011)", ""};
    } else if (r->a->product == GIS_SUN) {
        g.n_bands = 2;
        g.band[0] = (gis_band){v, "direct-beam irradiance on the tilted, shadowed surface "
                               "(clear sky)", "W/m^2"};
        g.band[1] = (gis_band){v ? v + n : NULL, "visible fraction of the sun's disk", ""};
    } else if (r->a->product == GIS_INSOLATION) {
        g.n_bands = gis_run_bands(r);
        g.band[0] = (gis_band){v, "beam irradiation (clear sky)", "Wh/m^2"};
        g.band[1] = (gis_band){v ? v + n : NULL, r->a->sky_map
                               ? "sky-diffuse irradiation (clear sky, the sky map's shape)"
                               : "sky-diffuse irradiation (clear sky, isotropic)", "Wh/m^2"};
        g.band[2] = (gis_band){v ? v + 2 * n : NULL, r->a->albedo > 0.0
                               ? "global irradiation (beam + sky-diffuse + ground-reflected)"
                               : "global irradiation (beam + sky-diffuse)", "Wh/m^2"};
    } else {
        g.n_bands = 2;
        g.band[0] = (gis_band){v, "positive openness (Yokoyama et al. 2002)", "degrees"};
        g.band[1] = (gis_band){v ? v + n : NULL, "negative openness (Yokoyama et al. 2002)",
                               "degrees"};
    }
    return g;
}

gis_raster gis_run_horizon_raster(const gis_run *r, int k, const float *deg,
                                  gis_horizon_text *t)
{
    snprintf(t->value, sizeof t->value, "%.*f", r->a->decimals,
             gis_wrap_degrees(r->a->azimuth[k]));
    snprintf(t->item, sizeof t->item, "HFS_AZIMUTH=%s", t->value);
    gis_raster g = gis_run_raster(r, t->item);
    snprintf(t->what, sizeof t->what, "horizon elevation angle at azimuth %s degrees (%s)",
             t->value, r->a->convention == GIS_COMPASS ? "clockwise from north"
                                                       : "counter-clockwise from east");
    g.band[0] = (gis_band){deg, t->what, "degrees"};
    g.plain = 1; /* angles in runs of 0: no predictor (gis_raster.h) */
    return g;
}
