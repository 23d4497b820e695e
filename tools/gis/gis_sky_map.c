/*
 * gis_sky_map.c — see gis_sky_map.h.
 */
#include "gis_sky_map.h"

#include "gis_products.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* The two parts of the closed form (gis_sky_add): the integral of
 * (n_z sin e + n_h cos e) cos e from e up to pi/2 is n_z a(e) + n_h b(e). */
static double part_a(double e)
{
    const double c = cos(e);
    return 0.5 * c * c;
}

static double part_b(double e)
{
    return 0.5 * (0.5 * PI - e) - 0.25 * sin(2.0 * e);
}

/* The integral of a row's luminance lum over the columns [0, x), x >= 0
 * in columns, the row repeating around the circle (prefix[i]: the sum of
 * columns 0 .. i - 1; prefix[w]: the whole row). */
static double row_integral(const double *prefix, const double *lum, int w, double x)
{
    const double turns = floor(x / w);
    double r = x - turns * w;
    int i = (int)floor(r);
    if (i >= w) /* x a hair below a whole turn */
        i = w - 1;
    return turns * prefix[w] + prefix[i] + (r - i) * lum[i];
}

/* Band j's row of the map (bands from the horizon up). */
static int band_row(const gis_sky_map *m, int j)
{
    return m->n_bands - 1 - j;
}

static int alloc(gis_sky_map *m, hfs_error *err, const char *name)
{
    const size_t nb = (size_t)m->n_bands, nd = (size_t)m->n_dirs;
    m->edge = malloc((nb + 1) * sizeof *m->edge);
    m->lum = malloc(nd * nb * sizeof *m->lum);
    m->sa = malloc(nd * (nb + 1) * sizeof *m->sa);
    m->sb = malloc(nd * (nb + 1) * sizeof *m->sb);
    if (m->edge && m->lum && m->sa && m->sb)
        return HFS_OK;
    const int dirs = m->n_dirs, bands = m->n_bands;
    gis_sky_map_free(m);
    return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for the sky's %d x %d table", name,
                    dirs, bands);
}

/* Band j's luminance in every azimuth's sector: the row's mean over the
 * sector, each column weighted by its part inside. 0, or -1 (a negative
 * or non-finite pixel at *col). */
static int band_sectors(gis_sky_map *m, const float *rgb, int w, int j, double north_deg,
                        const double *phi_map, double *prefix, double *lum, int *col)
{
    const float *px = rgb + (size_t)band_row(m, j) * (size_t)w * 3;
    prefix[0] = 0.0;
    for (int i = 0; i < w; ++i) {
        const double y = 0.2126 * px[3 * i] + 0.7152 * px[3 * i + 1] + 0.0722 * px[3 * i + 2];
        if (!(y >= 0.0) || !isfinite(y) || px[3 * i] < 0.0f || px[3 * i + 1] < 0.0f ||
            px[3 * i + 2] < 0.0f) {
            *col = i;
            return -1;
        }
        lum[i] = y;
        prefix[i + 1] = prefix[i] + y;
    }
    const double half = 0.5 / m->n_dirs; /* the sector's half width, turns */
    for (int k = 0; k < m->n_dirs; ++k) {
        const double compass = phi_map[k] * (180.0 / PI) + 90.0;
        double u = (compass - north_deg) / 360.0 - half;
        u -= floor(u);
        const double x0 = u * w, x1 = (u + 2.0 * half) * w;
        m->lum[(size_t)k * (size_t)m->n_bands + (size_t)j] =
            (row_integral(prefix, lum, w, x1) - row_integral(prefix, lum, w, x0)) / (x1 - x0);
    }
    return 0;
}

int gis_sky_map_make(const float *rgb, int w, int h, double north_deg, int n_dirs,
                     const char *name, gis_sky_map *out, hfs_error *err)
{
    gis_sky_map m = {.n_dirs = n_dirs, .n_bands = (h + 1) / 2};
    memset(out, 0, sizeof *out);
    double phi_map[HFS_MAX_HORIZON_AZIMUTHS];
    if (!(n_dirs >= 1 && n_dirs <= HFS_MAX_HORIZON_AZIMUTHS))
        return hfs_fail(err, HFS_E_INVALID, "%s: %d azimuths (1..%d)", name, n_dirs,
                        HFS_MAX_HORIZON_AZIMUTHS);
    gis_product_directions(phi_map, n_dirs);
    int rc = alloc(&m, err, name);
    if (rc)
        return rc;
    double *prefix = malloc(2 * ((size_t)w + 1) * sizeof *prefix);
    if (!prefix) {
        gis_sky_map_free(&m);
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", name);
    }
    double *lum = prefix + w + 1; /* a row's luminance, beside its sums */
    /* band j: row n_bands - 1 - j, from max(0, its lower edge) to its upper */
    for (int j = 0; j < m.n_bands; ++j)
        m.edge[j] = fmax(0.0, 0.5 * PI - PI * (band_row(&m, j) + 1) / h);
    m.edge[m.n_bands] = 0.5 * PI;
    for (int j = 0; j < m.n_bands; ++j) {
        int col = 0;
        if (band_sectors(&m, rgb, w, j, north_deg, phi_map, prefix, lum, &col)) {
            const int row = band_row(&m, j);
            free(prefix);
            gis_sky_map_free(&m);
            return hfs_fail(err, HFS_E_INVALID, "%s: pixel (%d, %d) of the sky is negative "
                            "or not finite (a sky's radiance is >= 0)", name, col, row);
        }
    }
    free(prefix);
    const size_t nb = (size_t)m.n_bands;
    for (int k = 0; k < n_dirs; ++k) {
        double *sa = m.sa + (size_t)k * (nb + 1), *sb = m.sb + (size_t)k * (nb + 1);
        const double *l = m.lum + (size_t)k * nb;
        sa[nb] = sb[nb] = 0.0;
        for (int j = m.n_bands - 1; j >= 0; --j) {
            sa[j] = sa[j + 1] + l[j] * (part_a(m.edge[j]) - part_a(m.edge[j + 1]));
            sb[j] = sb[j + 1] + l[j] * (part_b(m.edge[j]) - part_b(m.edge[j + 1]));
        }
        m.open += sa[0];
    }
    /* finite: floats summed in doubles, each band's weight at most 1/2 */
    if (!(m.open > 0.0)) {
        gis_sky_map_free(&m);
        return hfs_fail(err, HFS_E_INVALID, "%s: the sky (the map's upper half) is black: it "
                        "sends no light", name);
    }
    *out = m;
    return HFS_OK;
}

void gis_sky_map_free(gis_sky_map *m)
{
    free(m->edge);
    free(m->lum);
    free(m->sa);
    free(m->sb);
    memset(m, 0, sizeof *m);
}

/* The band holding elevation g in [0, pi/2): edge[j] <= g < edge[j + 1]. */
static int band_of(const gis_sky_map *m, double g)
{
    int lo = 0, hi = m->n_bands - 1;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (m->edge[mid] <= g)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

void gis_sky_map_add(const gis_sky_map *m, int k, double phi, double *acc, const float *gamma,
                     const float *n, size_t count)
{
    const double cp = cos(phi), sp = sin(phi);
    const size_t nb = (size_t)m->n_bands;
    const double *l = m->lum + (size_t)k * nb;
    const double *sa = m->sa + (size_t)k * (nb + 1), *sb = m->sb + (size_t)k * (nb + 1);
    for (size_t p = 0; p < count; ++p) {
        const double nx = n[3 * p], ny = n[3 * p + 1], nz = n[3 * p + 2];
        const double nh = nx * cp + ny * sp, t = atan2(-nh, nz);
        const double g = fmax(fmax((double)gamma[p], t), 0.0); /* NONE is -pi/2 */
        if (!(g < 0.5 * PI))
            continue;
        const int j = band_of(m, g);
        const double top = m->edge[j + 1];
        acc[p] += nz * (sa[j + 1] + l[j] * (part_a(g) - part_a(top))) +
                  nh * (sb[j + 1] + l[j] * (part_b(g) - part_b(top)));
    }
}

void gis_sky_map_finish(const gis_sky_map *m, float *out, const double *acc, size_t count)
{
    for (size_t p = 0; p < count; ++p)
        out[p] = (float)fmax(acc[p] / m->open, 0.0);
}
