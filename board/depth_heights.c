/*
 * depth_heights.c — see depth_heights.h.
 */
#include "depth_heights.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hfs_io.h"

struct hfs_depth_heights {
    hfs_depth_params p;
    int have_plane;
    double plane[3];
    int n_cells;
    double *sum;           /* resampling accumulators, per cell            */
    int *count;
    float *raw;            /* resampled heights, metres, NaN = hole        */
    float *ring;           /* window samples per cell                      */
    uint8_t *n, *pos;      /* samples held, next slot                      */
    float *shown;          /* the filter's output, metres, NaN = none yet  */
    float *z;              /* world units, holes filled                    */
};

void hfs_depth_params_defaults(hfs_depth_params *p)
{
    memset(p, 0, sizeof *p);
    p->scale = 0.001;
    p->zgain = 1.0;
    p->grid_w = 256, p->grid_h = 192;
    p->window = 8;
    p->gate = 0.003;
    p->hysteresis = 0.0025;
    p->jump = 0.010;
}

static int check_params(const hfs_depth_params *p, hfs_error *err)
{
    if (!(p->scale > 0.0 && p->scale < 1.0))
        return hfs_fail(err, HFS_E_INVALID, "depth_scale: %g is not in (0, 1) metres", p->scale);
    if (!(p->zgain > 0.0 && p->zgain <= 1e6))
        return hfs_fail(err, HFS_E_INVALID, "zgain: %g is not in (0, 1e6]", p->zgain);
    if (p->grid_w < 2 || p->grid_h < 2 || p->grid_w > 8192 || p->grid_h > 8192)
        return hfs_fail(err, HFS_E_INVALID, "grid: %dx%d is not 2..8192 per side", p->grid_w,
                        p->grid_h);
    if (p->window < 1 || p->window > HFS_DEPTH_WINDOW_MAX)
        return hfs_fail(err, HFS_E_INVALID, "window: %d is not in [1, %d]", p->window,
                        HFS_DEPTH_WINDOW_MAX);
    if (!(p->gate >= 0.0) || !(p->hysteresis >= 0.0) || !(p->jump > 0.0))
        return hfs_fail(err, HFS_E_INVALID, "filter: gate and hysteresis >= 0, jump > 0");
    if (p->roi[0] < 0 || p->roi[1] < 0 || p->roi[2] < 0 || p->roi[3] < 0 ||
        (p->roi[2] == 0) != (p->roi[3] == 0))
        return hfs_fail(err, HFS_E_INVALID, "roi: %d %d %d %d is not X Y W H (W, H > 0)",
                        p->roi[0], p->roi[1], p->roi[2], p->roi[3]);
    if (!(p->min_depth >= 0.0) || !(p->max_depth >= 0.0) ||
        (p->max_depth > 0.0 && p->max_depth <= p->min_depth))
        return hfs_fail(err, HFS_E_INVALID, "min_depth/max_depth: [%g, %g] is empty",
                        p->min_depth, p->max_depth);
    for (int i = 0; i < 3 && p->plane_set; ++i)
        if (!isfinite(p->plane[i]))
            return hfs_fail(err, HFS_E_INVALID, "plane: not finite");
    return HFS_OK;
}

int hfs_depth_heights_create(const hfs_depth_params *p, hfs_depth_heights **out,
                             hfs_error *err)
{
    *out = NULL;
    int rc = check_params(p, err);
    if (rc)
        return rc;
    hfs_depth_heights *h = calloc(1, sizeof *h);
    if (!h)
        return hfs_fail(err, HFS_E_NOMEM, "depth: out of memory");
    h->p = *p;
    h->n_cells = p->grid_w * p->grid_h;
    const size_t n = (size_t)h->n_cells;
    h->sum = malloc(n * sizeof *h->sum);
    h->count = malloc(n * sizeof *h->count);
    h->raw = malloc(n * sizeof *h->raw);
    h->ring = malloc(n * (size_t)p->window * sizeof *h->ring);
    h->n = calloc(n, 1);
    h->pos = calloc(n, 1);
    h->shown = malloc(n * sizeof *h->shown);
    h->z = calloc(n, sizeof *h->z);
    if (!h->sum || !h->count || !h->raw || !h->ring || !h->n || !h->pos || !h->shown || !h->z) {
        hfs_depth_heights_destroy(h);
        return hfs_fail(err, HFS_E_NOMEM, "depth: out of memory (grid %dx%d)", p->grid_w,
                        p->grid_h);
    }
    for (size_t i = 0; i < n; ++i)
        h->shown[i] = NAN;
    if (p->plane_set) {
        memcpy(h->plane, p->plane, sizeof h->plane);
        h->have_plane = 1;
    }
    *out = h;
    return HFS_OK;
}

void hfs_depth_heights_destroy(hfs_depth_heights *h)
{
    if (!h)
        return;
    free(h->sum);
    free(h->count);
    free(h->raw);
    free(h->ring);
    free(h->n);
    free(h->pos);
    free(h->shown);
    free(h->z);
    free(h);
}

/* Depth of pixel (u, v) in metres, or NaN when invalid. */
static double depth_at(const hfs_depth_params *p, const uint8_t *row, int u)
{
    const unsigned c = (unsigned)row[2 * u] | ((unsigned)row[2 * u + 1] << 8);
    const double d = c * p->scale;
    if (c == 0 || d < p->min_depth || (p->max_depth > 0.0 && d > p->max_depth))
        return NAN;
    return d;
}

static void roi_of(const hfs_depth_params *p, int width, int height, int r[4])
{
    if (p->roi[2] > 0) {
        memcpy(r, p->roi, 4 * sizeof *r);
    } else {
        r[0] = r[1] = 0;
        r[2] = width, r[3] = height;
    }
}

static int check_frame(const hfs_depth_params *p, int width, int height, int stride,
                       hfs_error *err)
{
    int r[4];
    roi_of(p, width, height, r);
    if (width < 1 || height < 1 || stride < 2 * width)
        return hfs_fail(err, HFS_E_FORMAT, "depth frame %dx%d stride %d: bad geometry", width,
                        height, stride);
    if (r[0] + r[2] > width || r[1] + r[3] > height)
        return hfs_fail(err, HFS_E_INVALID, "roi: %d %d %d %d is outside the %dx%d frame", r[0],
                        r[1], r[2], r[3], width, height);
    return HFS_OK;
}

/* Solves the 3x3 system m x = b (Gaussian elimination, partial pivoting). */
static int solve3(double m[3][3], double b[3], double x[3])
{
    for (int c = 0; c < 3; ++c) {
        int piv = c;
        for (int r = c + 1; r < 3; ++r)
            if (fabs(m[r][c]) > fabs(m[piv][c]))
                piv = r;
        if (fabs(m[piv][c]) < 1e-12)
            return -1;
        for (int k = 0; k < 3; ++k) {
            const double t = m[c][k];
            m[c][k] = m[piv][k], m[piv][k] = t;
        }
        const double t = b[c];
        b[c] = b[piv], b[piv] = t;
        for (int r = c + 1; r < 3; ++r) {
            const double f = m[r][c] / m[c][c];
            for (int k = c; k < 3; ++k)
                m[r][k] -= f * m[c][k];
            b[r] -= f * b[c];
        }
    }
    for (int r = 2; r >= 0; --r) {
        double s = b[r];
        for (int k = r + 1; k < 3; ++k)
            s -= m[r][k] * x[k];
        x[r] = s / m[r][r];
    }
    return 0;
}

int hfs_depth_fit_plane(const hfs_depth_params *p, const uint8_t *depth, int width, int height,
                        int stride, double plane[3], hfs_error *err)
{
    int rc = check_frame(p, width, height, stride, err);
    if (rc)
        return rc;
    int r[4];
    roi_of(p, width, height, r);
    /* Centred coordinates keep the normal equations well conditioned. */
    const double cu = r[0] + 0.5 * r[2], cv = r[1] + 0.5 * r[3];
    double m[3][3] = {{0}}, b[3] = {0};
    long n = 0;
    for (int v = r[1]; v < r[1] + r[3]; ++v) {
        const uint8_t *row = depth + (size_t)v * (size_t)stride;
        for (int u = r[0]; u < r[0] + r[2]; ++u) {
            const double d = depth_at(p, row, u);
            if (isnan(d))
                continue;
            const double x[3] = {u - cu, v - cv, 1.0};
            for (int i = 0; i < 3; ++i) {
                for (int k = 0; k < 3; ++k)
                    m[i][k] += x[i] * x[k];
                b[i] += x[i] * d;
            }
            n++;
        }
    }
    double s[3];
    if (n < 3 || solve3(m, b, s))
        return hfs_fail(err, HFS_E_FORMAT, "plane: %ld valid depth pixels in the roi, not "
                        "enough for a plane", n);
    plane[0] = s[0];
    plane[1] = s[1];
    plane[2] = s[2] - s[0] * cu - s[1] * cv;
    return HFS_OK;
}

/* Steps 1-3: h->raw, metres above the plane, NaN where no valid pixel. */
static long resample(hfs_depth_heights *h, const uint8_t *depth, int width, int height,
                     int stride)
{
    const hfs_depth_params *p = &h->p;
    int r[4];
    roi_of(p, width, height, r);
    memset(h->sum, 0, (size_t)h->n_cells * sizeof *h->sum);
    memset(h->count, 0, (size_t)h->n_cells * sizeof *h->count);
    const double *pl = h->plane;
    for (int v = r[1]; v < r[1] + r[3]; ++v) {
        const uint8_t *row = depth + (size_t)v * (size_t)stride;
        const int j = (int)((long)(v - r[1]) * p->grid_h / r[3]);
        for (int u = r[0]; u < r[0] + r[2]; ++u) {
            const double d = depth_at(p, row, u);
            if (isnan(d))
                continue;
            const int i = (int)((long)(u - r[0]) * p->grid_w / r[2]);
            h->sum[j * p->grid_w + i] += pl[0] * u + pl[1] * v + pl[2] - d;
            h->count[j * p->grid_w + i]++;
        }
    }
    long valid = 0;
    for (int j = 0; j < p->grid_h; ++j)
        for (int i = 0; i < p->grid_w; ++i) {
            const int c = j * p->grid_w + i;
            double hv = h->count[c] ? h->sum[c] / h->count[c] : NAN;
            if (!h->count[c]) { /* a grid finer than the roi: the centre pixel */
                const int u = r[0] + (int)((i + 0.5) * r[2] / p->grid_w);
                const int v = r[1] + (int)((j + 0.5) * r[3] / p->grid_h);
                const double d = depth_at(p, depth + (size_t)v * (size_t)stride, u);
                hv = pl[0] * u + pl[1] * v + pl[2] - d;
            }
            h->raw[c] = (float)hv;
            valid += !isnan(hv);
        }
    return valid;
}

/* Step 4 for one cell: 1 when its shown height changed. */
static int filter_cell(hfs_depth_heights *h, int c, float s)
{
    const hfs_depth_params *p = &h->p;
    float *ring = h->ring + (size_t)c * (size_t)p->window;
    if (isnan(s))
        return 0;
    double mean = 0.0;
    for (int k = 0; k < h->n[c]; ++k)
        mean += ring[k];
    if (h->n[c] == 0 || fabs(s - mean / h->n[c]) > p->jump) {
        ring[0] = s;
        h->n[c] = 1;
        h->pos[c] = 1 % p->window;
        const int changed = h->shown[c] != s;
        h->shown[c] = s;
        return changed;
    }
    ring[h->pos[c]] = s;
    h->pos[c] = (uint8_t)((h->pos[c] + 1) % p->window);
    if (h->n[c] < p->window)
        h->n[c]++;
    const int n = h->n[c];
    mean = 0.0;
    for (int k = 0; k < n; ++k)
        mean += ring[k];
    mean /= n;
    double var = 0.0;
    for (int k = 0; k < n; ++k)
        var += (ring[k] - mean) * (ring[k] - mean);
    var /= n;
    /* Filling after a jump: the mean as it grows (the cell follows). */
    const int filling = n < p->window;
    if (!filling && (var > p->gate * p->gate || fabs(mean - h->shown[c]) <= p->hysteresis))
        return 0;
    if ((float)mean == h->shown[c])
        return 0;
    h->shown[c] = (float)mean;
    return 1;
}

int hfs_depth_heights_push(hfs_depth_heights *h, const uint8_t *depth, int width, int height,
                           int stride, hfs_error *err)
{
    int rc = check_frame(&h->p, width, height, stride, err);
    if (rc)
        return rc;
    if (!h->have_plane) {
        if ((rc = hfs_depth_fit_plane(&h->p, depth, width, height, stride, h->plane, err)))
            return rc;
        h->have_plane = 1;
    }
    if (resample(h, depth, width, height, stride) == 0)
        return hfs_fail(err, HFS_E_FORMAT, "depth frame: no valid pixel in the roi");
    int changed = 0;
    for (int c = 0; c < h->n_cells; ++c)
        changed |= filter_cell(h, c, h->raw[c]);
    if (!changed)
        return 0;
    for (int c = 0; c < h->n_cells; ++c)
        h->z[c] = (float)(h->shown[c] * h->p.zgain); /* NaN stays NaN: a hole */
    hfs_error e;
    if (hfs_height_fill_holes(h->z, h->p.grid_w, h->p.grid_h, 0, 0.0f, NULL, &e)) {
        memset(h->z, 0, (size_t)h->n_cells * sizeof *h->z); /* never NaN out */
        return hfs_fail(err, HFS_E_FORMAT, "depth frame: %s", e.msg);
    }
    return 1;
}

const float *hfs_depth_heights_z(const hfs_depth_heights *h)
{
    return h->z;
}

int hfs_depth_heights_plane(const hfs_depth_heights *h, double plane[3])
{
    if (h->have_plane)
        memcpy(plane, h->plane, sizeof h->plane);
    return h->have_plane;
}

const float *hfs_depth_heights_raw(const hfs_depth_heights *h)
{
    return h->raw;
}

void hfs_depth_heights_grid(const hfs_depth_heights *h, int *width, int *height)
{
    *width = h->p.grid_w;
    *height = h->p.grid_h;
}
