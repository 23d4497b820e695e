/*
 * shm.c — see shm.h.
 */
#include "shm.h"

#include "parallel.h"

#include <math.h>

#define PI 3.14159265358979323846

int hfs_shm_passes(int w, int h)
{
    /* Every distance within the grid's diagonal: 2^J > sqrt(w^2 + h^2). */
    const double diag = sqrt((double)w * w + (double)h * h);
    int j = 0;
    while (j < 30 && ldexp(1.0, j) <= diag)
        ++j;
    return j;
}

double hfs_shm_layer_elevation(double elev, double alpha, int k)
{
    return elev + alpha * (2.0 * k / (HFS_SHM_LAYERS - 1) - 1.0);
}

double hfs_shm_sample(const float *s, int w, int h, double gx, double gy)
{
    gx = gx < 0.0 ? 0.0 : (gx > w - 1.0 ? w - 1.0 : gx);
    gy = gy < 0.0 ? 0.0 : (gy > h - 1.0 ? h - 1.0 : gy);
    int i = (int)gx, j = (int)gy;
    i = i > w - 2 ? w - 2 : i;
    j = j > h - 2 ? h - 2 : j;
    const double fx = gx - i, fy = gy - j;
    const float *r0 = s + (size_t)j * (size_t)w + (size_t)i, *r1 = r0 + w;
    const double a = r0[0] + fx * ((double)r0[1] - r0[0]);
    const double b = r1[0] + fx * ((double)r1[1] - r1[0]);
    return a + fy * (b - a);
}

typedef struct pass_ctx {
    int w, h;
    const float *src;
    float *dst;
    double ox, oy;   /* the step towards the light, texels */
    double drop;     /* the ray's rise over the step, world z */
} pass_ctx;

/* One doubling pass over row j: S_{j+1} = max(S_j, S_j(x + o) - drop). */
static void pass_row(void *vctx, int j, int worker)
{
    (void)worker;
    const pass_ctx *c = vctx;
    const double slack = 1e-9 * (1.0 + fabs(c->ox) + fabs(c->oy));
    for (int i = 0; i < c->w; ++i) {
        const size_t p = (size_t)j * (size_t)c->w + (size_t)i;
        double v = c->src[p];
        const double gx = i + c->ox, gy = j + c->oy;
        if (gx >= -slack && gy >= -slack && gx <= c->w - 1 + slack && gy <= c->h - 1 + slack) {
            const double far = hfs_shm_sample(c->src, c->w, c->h, gx, gy) - c->drop;
            v = far > v ? far : v;
        }
        c->dst[p] = (float)v;
    }
}

void hfs_shm_build(const hfs_field *f, double phi, double elev, float *s, float *scratch,
                   int threads)
{
    const int w = f->width, h = f->height;
    const size_t n = (size_t)w * (size_t)h;
    for (size_t p = 0; p < n; ++p)
        s[p] = (float)(f->zscale * f->z[p]);
    /* A light at or past the zenith: nothing casts a shadow. */
    if (!(elev < 0.5 * PI - 1e-9))
        return;
    const int passes = hfs_shm_passes(w, h);
    const double c = cos(phi), sn = sin(phi), slope = f->dx * tan(elev);
    float *src = s, *dst = scratch;
    for (int j = 0; j < passes; ++j) {
        const double step = ldexp(1.0, j);
        pass_ctx ctx = {w, h, src, dst, step * c, step * sn, step * slope};
        hfs_parallel_rows(h, threads, pass_row, &ctx, NULL, NULL);
        float *t = src;
        src = dst;
        dst = t;
    }
    if (src != s)
        for (size_t p = 0; p < n; ++p)
            s[p] = src[p];
}

double hfs_shm_disk_fraction(const double s[HFS_SHM_LAYERS], double z)
{
    if (z >= s[0])
        return 1.0; /* the disk's lowest edge is in view */
    if (!(z >= s[HFS_SHM_LAYERS - 1]))
        return 0.0; /* its highest edge is not */
    int k = 0;
    while (k < HFS_SHM_LAYERS - 2 && z < s[k + 1])
        ++k;
    /* s[k + 1] <= z < s[k]: the elevation where S crosses z, in disk radii. */
    const double t = s[k] > s[k + 1] ? (s[k] - z) / (s[k] - s[k + 1]) : 1.0;
    const double hh = (2.0 * (k + t)) / (HFS_SHM_LAYERS - 1) - 1.0;
    const double hc = hh < -1.0 ? -1.0 : (hh > 1.0 ? 1.0 : hh);
    return (acos(hc) - hc * sqrt(1.0 - hc * hc)) / PI;
}
