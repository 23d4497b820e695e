/*
 * capture_synth_sky.c — see capture_synth_sky.h.
 */
#include "capture_synth_sky.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "capture_record.h"
#include "capture_synth.h"

#define PI 3.14159265358979323846

static double gauss(uint64_t *s)
{
    const double a = hfs_synth_uniform(s), b = hfs_synth_uniform(s);
    return sqrt(-2.0 * log(a)) * cos(2.0 * PI * b);
}

/* Linear [0, 1] to the transfer's code value in [0, 1]. */
static double encode(const hfs_camenv_params *p, double v)
{
    v = v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
    if (p->linear)
        return v;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

static uint8_t code8(double v)
{
    const long c = lround(v);
    return (uint8_t)(c < 0 ? 0 : c > 255 ? 255 : c);
}

/* Pixel (x, y)'s radiance, 2 x 2 samples; 0 where nothing is seen. */
static void pixel_radiance(const hfs_camenv_params *p, int w, int h, int x, int y,
                           hfs_sky_fn sky, void *user, double rgb[3])
{
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    for (int s = 0; s < 4; ++s) {
        double d[3], c[3];
        if (!hfs_camenv_pixel_to_dir(p, w, h, x + 0.25 + 0.5 * (s & 1), y + 0.25 + 0.5 * (s >> 1),
                                     d))
            continue;
        sky(user, d, c);
        for (int k = 0; k < 3; ++k)
            rgb[k] += 0.25 * c[k];
    }
}

void hfs_synth_sky_render(const hfs_camenv_params *p, int w, int h, hfs_pixfmt fmt,
                          hfs_sky_fn sky, void *user, double noise, uint64_t *rng,
                          uint8_t *out)
{
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; x += 2) {
            double ycc[2][3];
            for (int i = 0; i < 2; ++i) {
                double rgb[3], e[3];
                pixel_radiance(p, w, h, x + i < w ? x + i : x, y, sky, user, rgb);
                for (int k = 0; k < 3; ++k)
                    e[k] = encode(p, rgb[k] / p->exposure);
                const double n = rng && noise > 0.0 ? noise * gauss(rng) : 0.0;
                if (fmt == HFS_PIX_GREY) {
                    ycc[i][0] = 255.0 * encode(p, (0.2126 * rgb[0] + 0.7152 * rgb[1] +
                                                   0.0722 * rgb[2]) / p->exposure) + n;
                    continue;
                }
                ycc[i][0] = 16.0 + 65.481 * e[0] + 128.553 * e[1] + 24.966 * e[2] + n;
                ycc[i][1] = 128.0 - 37.797 * e[0] - 74.203 * e[1] + 112.0 * e[2];
                ycc[i][2] = 128.0 + 112.0 * e[0] - 93.786 * e[1] - 18.214 * e[2];
            }
            if (fmt == HFS_PIX_GREY) {
                out[(size_t)y * w + x] = code8(ycc[0][0]);
                if (x + 1 < w)
                    out[(size_t)y * w + x + 1] = code8(ycc[1][0]);
                continue;
            }
            uint8_t *q = out + (size_t)y * 2 * w + 2 * x;
            q[0] = code8(ycc[0][0]);
            q[1] = code8(0.5 * (ycc[0][1] + ycc[1][1]));
            q[2] = code8(ycc[1][0]);
            q[3] = code8(0.5 * (ycc[0][2] + ycc[1][2]));
        }
}

void hfs_synth_sky_defaults(hfs_synth_sky_desc *d)
{
    memset(d, 0, sizeof *d);
    hfs_camenv_defaults(&d->cam);
    d->width = 320, d->height = 240;
    d->frames = 60;
    d->fps = 30.0;
    d->az_from = 30.0, d->az_to = 150.0, d->elev = 40.0;
    d->sun_radius = 8.0;
    d->noise = 1.5;
    d->seed = 1;
}

void hfs_synth_sky_sun(const hfs_synth_sky_desc *d, int k, double *az, double *elev)
{
    const double t = d->frames > 1 ? (double)k / (d->frames - 1) : 0.0;
    *az = d->az_from + t * (d->az_to - d->az_from);
    *elev = d->elev;
}

void hfs_synth_sky_radiance(void *user, const double d[3], double rgb[3])
{
    const hfs_synth_sky_at *at = user;
    double az, el;
    hfs_synth_sky_sun(at->d, at->k, &az, &el);
    az *= PI / 180.0, el *= PI / 180.0;
    const double s[3] = {cos(az) * cos(el), sin(az) * cos(el), sin(el)};
    const double cs = d[0] * s[0] + d[1] * s[1] + d[2] * s[2];
    if (cs >= cos(at->d->sun_radius * PI / 180.0)) {
        rgb[0] = rgb[1] = rgb[2] = 1.0;
        return;
    }
    const double up = d[2] > 0.0 ? d[2] : 0.0;
    const double g = d[2] >= 0.0 ? 1.0 : 0.5; /* the ground is darker */
    rgb[0] = g * (0.02 + 0.01 * up);
    rgb[1] = g * (0.03 + 0.015 * up);
    rgb[2] = g * (0.04 + 0.02 * up) * (d[2] >= 0.0 ? 1.0 : 0.5);
}

void hfs_synth_sky_frame(const hfs_synth_sky_desc *d, int k, uint8_t *yuyv)
{
    hfs_synth_sky_at at = {d, k};
    uint64_t rng = ((uint64_t)d->seed << 32) ^ (uint64_t)(uint32_t)k;
    hfs_synth_sky_render(&d->cam, d->width, d->height, HFS_PIX_YUYV, hfs_synth_sky_radiance, &at,
                         d->noise, &rng, yuyv);
}

int hfs_synth_sky_record(const hfs_synth_sky_desc *d, const char *dir, hfs_error *err)
{
    const size_t n = (size_t)d->width * (size_t)d->height * 2;
    uint8_t *bytes = malloc(n);
    if (!bytes)
        return hfs_fail(err, HFS_E_NOMEM, "synth: out of memory");
    hfs_capture_recorder *r = NULL;
    int rc = hfs_capture_record_open(dir, &r, err);
    for (int k = 0; k < d->frames && !rc; ++k) {
        hfs_synth_sky_frame(d, k, bytes);
        const hfs_capture_frame f = {.data = bytes, .bytes = n, .width = d->width,
                                     .height = d->height, .stride = 2 * d->width,
                                     .format = HFS_PIX_YUYV, .sequence = (uint32_t)k,
                                     .t_ns = 1000000000LL + (int64_t)llround(k * 1e9 / d->fps)};
        rc = hfs_capture_record_frame(r, &f, err);
    }
    const int rc2 = hfs_capture_record_close(r, rc ? NULL : err);
    free(bytes);
    return rc ? rc : rc2;
}
