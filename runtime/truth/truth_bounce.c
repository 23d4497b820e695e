/*
 * truth_bounce.c — see truth_bounce.h.
 */
#include "truth_bounce.h"

#include "field_geom.h"
#include "parallel.h"
#include "truth_sampling.h"

#include <math.h>

#define PI 3.14159265358979323846
#define BOUNCE_SLOT0 4096   /* RNG slots of bounces: apart from the lights' */

typedef struct bounce_ctx {
    const hfs_truth_bounce_in *in;
    float *out;
} bounce_ctx;

/* Strata per axis: the largest k with k^2 <= samples (at least 1). */
static int strata(int samples)
{
    int k = (int)floor(sqrt((double)samples));
    while ((long)(k + 1) * (k + 1) <= samples)
        ++k;
    while (k > 1 && (long)k * k > samples)
        --k;
    return k < 1 ? 1 : k;
}

/* Mean of Lo_{b-1} over the receiver's k x k cosine-weighted strata. */
static void gather(const hfs_truth_bounce_in *in, int i, int j, double mean[3])
{
    const hfs_field *f = in->grid->f;
    double n[3], t1[3], t2[3];
    hfs_field_normal(f, i, j, n);
    frame_around(n, t1, t2);
    const double o[3] = {i, j, hfs_field_lifted_z(f, i, j)};
    uint64_t rng = rng_seed((uint64_t)j * (uint64_t)f->width + (uint64_t)i,
                            BOUNCE_SLOT0 + in->bounce);
    const int k = strata(in->samples);
    mean[0] = mean[1] = mean[2] = 0.0;
    for (int a = 0; a < k; ++a)
        for (int q = 0; q < k; ++q) {
            const double r2 = ((double)a + rng_uniform(&rng)) / k;
            const double psi = 2.0 * PI * ((double)q + rng_uniform(&rng)) / k;
            const double r = sqrt(r2), cz = sqrt(fmax(0.0, 1.0 - r2));
            const double lx = r * cos(psi), ly = r * sin(psi);
            double d[3], t;
            for (int c = 0; c < 3; ++c)
                d[c] = lx * t1[c] + ly * t2[c] + cz * n[c];
            if (!hfs_truth_ray_first_hit(in->grid, o, d, INFINITY, &t))
                continue;
            double lo[3];
            hfs_rgb_bilinear(in->prev, f->width, f->height, o[0] + t * d[0] / f->dx,
                             o[1] + t * d[1] / f->dx, lo);
            for (int c = 0; c < 3; ++c)
                mean[c] += lo[c];
        }
    for (int c = 0; c < 3; ++c)
        mean[c] /= (double)k * k;
}

/* The glossy share: ks (S+2)/(S+1) times the mean of Lo_{b-1} max(0, N.s)
 * over the k x k strata of the lobe about R (its own jitter stream). */
static void gather_lobe(const hfs_truth_bounce_in *in, int i, int j, double out[3])
{
    const hfs_field *f = in->grid->f;
    const hfs_gloss *gl = in->gloss;
    double n[3], r[3], t1[3], t2[3];
    hfs_field_normal(f, i, j, n);
    const double pw[3] = {i * f->dx, j * f->dx, hfs_field_z(f, i, j)};
    out[0] = out[1] = out[2] = 0.0;
    if (!(hfs_gloss_reflect(gl, pw, n, r) > 0.0))
        return;
    frame_around(r, t1, t2);
    const double o[3] = {i, j, hfs_field_lifted_z(f, i, j)};
    uint64_t rng = rng_seed((uint64_t)j * (uint64_t)f->width + (uint64_t)i,
                            BOUNCE_SLOT0 + 16 + in->bounce);
    const int k = strata(in->samples);
    for (int a = 0; a < k; ++a)
        for (int q = 0; q < k; ++q) {
            const double u1 = ((double)a + rng_uniform(&rng)) / k;
            const double u2 = ((double)q + rng_uniform(&rng)) / k;
            double d[3], t;
            lobe_direction(r, t1, t2, 1.0 / (gl->s + 1.0), u1, u2, d);
            const double ns = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
            if (!(ns > 0.0) || !hfs_truth_ray_first_hit(in->grid, o, d, INFINITY, &t))
                continue;
            double lo[3];
            hfs_rgb_bilinear(in->prev, f->width, f->height, o[0] + t * d[0] / f->dx,
                             o[1] + t * d[1] / f->dx, lo);
            for (int c = 0; c < 3; ++c)
                out[c] += ns * lo[c];
        }
    for (int c = 0; c < 3; ++c)
        out[c] *= gl->ks * (gl->s + 2.0) / (gl->s + 1.0) / ((double)k * k);
}

void hfs_truth_bounce_at(const hfs_truth_bounce_in *in, int i, int j, double lo[3])
{
    gather(in, i, j, lo);
    const size_t p = 3 * ((size_t)j * (size_t)in->grid->f->width + (size_t)i);
    for (int c = 0; c < 3; ++c)
        lo[c] *= in->albedo * (in->albedo_map ? in->albedo_map[p + c] : 1.0);
    if (in->gloss && in->gloss->on) { /* not the albedo map's, as the direct lobe */
        double sp[3];
        gather_lobe(in, i, j, sp);
        for (int c = 0; c < 3; ++c)
            lo[c] += sp[c];
    }
}

static void bounce_row(void *ctx, int j, int worker)
{
    (void)worker;
    const bounce_ctx *b = ctx;
    const int w = b->in->grid->f->width;
    for (int i = 0; i < w; ++i) {
        double lo[3];
        hfs_truth_bounce_at(b->in, i, j, lo);
        for (int c = 0; c < 3; ++c)
            b->out[3 * ((size_t)j * (size_t)w + (size_t)i) + (size_t)c] = (float)lo[c];
    }
}

void hfs_truth_bounce(const hfs_truth_bounce_in *in, float *out, hfs_progress_fn progress,
                      void *user)
{
    bounce_ctx b = {in, out};
    hfs_parallel_rows(in->grid->f->height, in->threads, bounce_row, &b, progress, user);
}
