/*
 * capture_synth.c — see capture_synth.h.
 */
#include "capture_synth.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "capture_record.h"

#define PI 3.14159265358979323846

void hfs_synth_defaults(hfs_synth_desc *d)
{
    memset(d, 0, sizeof *d);
    d->width = 512, d->height = 384;
    d->frames = 90;
    d->fps = 30.0;
    d->scale = 0.001;
    d->noise_m = 0.0015;
    d->hole_frac = 0.005;
    d->hand_from = 30, d->hand_stop = 45, d->hand_to = 70;
    d->seed = 1;
}

void hfs_synth_plane(const hfs_synth_desc *d, double plane[3])
{
    /* 1 m at the centre, tilted ~1.2 cm across the width. */
    plane[0] = 0.012 / d->width;
    plane[1] = -0.006 / d->height;
    plane[2] = 1.0 - plane[0] * 0.5 * d->width - plane[1] * 0.5 * d->height;
}

/* splitmix64: a deterministic stream per (seed, frame). */
uint64_t hfs_synth_u64(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double hfs_synth_uniform(uint64_t *s)
{
    return ((double)(hfs_synth_u64(s) >> 11) + 0.5) / 9007199254740992.0;
}

static double sand(const hfs_synth_desc *d, int u, int v)
{
    const double x = (double)u / d->width, y = (double)v / d->height;
    const double dune = 0.03 + 0.02 * sin(2.0 * PI * (1.5 * x + 0.3 * y)) * cos(2.0 * PI * y);
    const double hx = x - 0.3, hy = y - 0.6;
    return dune + 0.05 * exp(-(hx * hx + hy * hy) / (2.0 * 0.01));
}

/* Where the hand is at frame k (centre, in pixels); 0 when absent. */
static int hand_at(const hfs_synth_desc *d, int k, double *cx, double *cy)
{
    if (d->hand_from < 0 || k < d->hand_from || k >= d->hand_to)
        return 0;
    const int stop = d->hand_stop > d->hand_from ? d->hand_stop : d->hand_from + 1;
    const double t = k >= stop ? 1.0 : (double)(k - d->hand_from) / (stop - d->hand_from);
    *cx = (0.2 + 0.5 * t) * d->width;
    *cy = 0.45 * d->height;
    return 1;
}

void hfs_synth_frame(const hfs_synth_desc *d, int k, uint16_t *depth, float *truth)
{
    double pl[3], cx = 0, cy = 0;
    hfs_synth_plane(d, pl);
    const int hand = hand_at(d, k, &cx, &cy);
    const double rx = 0.08 * d->width, ry = 0.12 * d->height;
    uint64_t rng = ((uint64_t)d->seed << 32) ^ (uint64_t)(uint32_t)k;
    for (int v = 0; v < d->height; ++v)
        for (int u = 0; u < d->width; ++u) {
            const double ex = (u - cx) / rx, ey = (v - cy) / ry;
            const int on_hand = hand && ex * ex + ey * ey <= 1.0;
            /* The projector's shadow: a strip right of the hand. */
            const int shadow = hand && !on_hand && ey * ey <= 1.0 && u > cx &&
                               u - cx <= rx * sqrt(1.0 - ey * ey) + 0.02 * d->width;
            const double h = on_hand ? 0.25 : sand(d, u, v);
            /* Box-Muller, one normal per pixel. */
            const double a = hfs_synth_uniform(&rng), b = hfs_synth_uniform(&rng), hole = hfs_synth_uniform(&rng);
            const double n = sqrt(-2.0 * log(a)) * cos(2.0 * PI * b) * d->noise_m;
            const double depth_m = pl[0] * u + pl[1] * v + pl[2] - h + n;
            long c = lround(depth_m / d->scale);
            if (shadow || hole < d->hole_frac || c < 0)
                c = 0;
            depth[(size_t)v * d->width + u] = (uint16_t)(c > 65535 ? 65535 : c);
            if (truth)
                truth[(size_t)v * d->width + u] = (float)h;
        }
}

int hfs_synth_record(const hfs_synth_desc *d, const char *dir, hfs_error *err)
{
    const size_t n = (size_t)d->width * (size_t)d->height;
    uint16_t *depth = malloc(n * sizeof *depth);
    uint8_t *bytes = malloc(2 * n);
    if (!depth || !bytes) {
        free(depth);
        free(bytes);
        return hfs_fail(err, HFS_E_NOMEM, "synth: out of memory");
    }
    hfs_capture_recorder *r = NULL;
    int rc = hfs_capture_record_open(dir, &r, err);
    for (int k = 0; k < d->frames && !rc; ++k) {
        hfs_synth_frame(d, k, depth, NULL);
        for (size_t i = 0; i < n; ++i) { /* little-endian, whatever the host */
            bytes[2 * i] = (uint8_t)(depth[i] & 0xff);
            bytes[2 * i + 1] = (uint8_t)(depth[i] >> 8);
        }
        const hfs_capture_frame f = {.data = bytes, .bytes = 2 * n, .width = d->width,
                                     .height = d->height, .stride = 2 * d->width,
                                     .format = HFS_PIX_Z16, .sequence = (uint32_t)k,
                                     .t_ns = 1000000000LL + (int64_t)llround(k * 1e9 / d->fps)};
        rc = hfs_capture_record_frame(r, &f, err);
    }
    const int rc2 = hfs_capture_record_close(r, rc ? NULL : err);
    free(depth);
    free(bytes);
    return rc ? rc : rc2;
}
