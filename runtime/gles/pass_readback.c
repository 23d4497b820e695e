/*
 * pass_readback.c — the lit targets (hi, lo: hfs_gles_lit_targets) read back, summed in
 * double, the output scale divided out (pass_shade.c), into the caller's
 * image; the image is also kept, handed out again while nothing changes.
 * The halves the driver reads are widened in the same loop that sums them
 * (half.h; no float copy of either target: at 1024² that was two 16 MiB
 * buffers written and read again a frame).
 */
#include "gles_backend.h"

#include "gl_util.h"
#include "half.h"
#include "parallel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The sum on worker threads from 256k pixels (as layout.c's split:
 * hfs_parallel_ranges, each chunk writing its own pixels). */
#define SUM_THREADED 262144
typedef struct sum_job {
    const uint16_t *hi, *lo;
    double inv;
    float *rgb;
} sum_job;

static void sum_range(void *ctx, size_t a, size_t b, int chunk)
{
    (void)chunk;
    const sum_job *j = ctx;
    hfs_half_sum_rgb(j->hi + 4 * a, j->lo + 4 * a, b - a, j->inv, j->rgb + 3 * a);
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const size_t npx = (size_t)L->w * L->h, n_img = npx * 3;
    float *px = hfs_gles_scratch(g, npx * 8 * sizeof(float));
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the readback");
    float *lo = px + npx * 4;
    /* The lit result (hfs_gles_lit_targets): hi, then lo alone. */
    const GLuint hi_fbo = fr->bounces > 0 ? g->bounce.fin_fbo : g->r.out_fbo;
    const GLuint lo_fbo = fr->bounces > 0 ? g->bounce.fin_lo_fbo : g->r.out_lo_fbo;
    hfs_gl_read_path th, tl;
    int rc;
    if ((rc = hfs_gl_read_rgba_raw(gl, hi_fbo, 0, 0, L->w, L->h, HFS_GL_READ_AUTO, px, &th,
                                   err)) ||
        (rc = hfs_gl_read_rgba_raw(gl, lo_fbo, 0, 0, L->w, L->h, HFS_GL_READ_AUTO, lo, &tl,
                                   err)))
        return rc;
    const double inv = 1.0 / fr->out_scale;
    float *rgb = fr->out->rgb;
    if (th == HFS_GL_READ_HALF && tl == HFS_GL_READ_HALF) {
        sum_job j = {(const uint16_t *)(void *)px, (const uint16_t *)(void *)lo, inv, rgb};
        hfs_parallel_ranges(npx, SUM_THREADED, sum_range, &j);
    } else {
        /* a driver that reads floats (or one target each way): widen what
         * came as halves, then the same sum */
        if (th == HFS_GL_READ_HALF)
            hfs_gl_widen_halves(px, npx * 4);
        if (tl == HFS_GL_READ_HALF)
            hfs_gl_widen_halves(lo, npx * 4);
        for (size_t i = 0; i < npx; ++i)
            for (int c = 0; c < 3; ++c) {
                const double v = ((double)px[4 * i + (size_t)c] + lo[4 * i + (size_t)c]) * inv;
                rgb[3 * i + (size_t)c] = isfinite(v) ? (float)v : 0.0f;
            }
    }
    if (g->last_img_cap < n_img) {
        float *k = realloc(g->last_img, n_img * sizeof *k);
        if (!k)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the kept image");
        g->last_img = k;
        g->last_img_cap = n_img;
    }
    memcpy(g->last_img, rgb, n_img * sizeof *rgb);
    return HFS_OK;
}

const hfs_gles_pass hfs_pass_readback = {
    .id = HFS_PASS_READBACK,
    .plan_name = "readback",
    .scope = HFS_SCOPE_FRAME,
    /* And the bounced targets when the frame has bounces (plan.c). */
    .reads = {"output targets", "bounce settings"},
    .writes = {"image"},
    .stages = {"readback"},
    .run = run,
};
