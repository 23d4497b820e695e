/*
 * sky_gen.c — synthetic skies (sky_gen.h).
 */
#include "sky_gen.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#define DEG (M_PI / 180.0)
#define SUB 8

void hfs_sky_defaults(hfs_sky_desc *d, int width, int height)
{
    static const float zen[3] = {0.25f, 0.45f, 0.95f}, hor[3] = {0.9f, 0.95f, 1.05f},
                       gnd[3] = {0.20f, 0.17f, 0.13f};
    memset(d, 0, sizeof *d);
    d->width = width;
    d->height = height;
    memcpy(d->zenith, zen, sizeof zen);
    memcpy(d->horizon, hor, sizeof hor);
    memcpy(d->ground, gnd, sizeof gnd);
}

static double lum(const float *p)
{
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

/* Uniform in [-1, 1) from an integer hash of (i, j, seed). */
static double hash_unit(unsigned i, unsigned j, unsigned seed)
{
    uint32_t x = i * 0x9E3779B1u ^ (j + 0x7F4A7C15u) * 0x85EBCA77u ^ seed * 0xC2B2AE3Du;
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return (double)x / 2147483648.0 - 1.0;
}

static void sky_at(const hfs_sky_desc *d, double e, float out[3])
{
    const double s = sin(e);
    for (int c = 0; c < 3; ++c)
        out[c] = e >= 0.0 ? (float)(d->horizon[c] + (d->zenith[c] - d->horizon[c]) * s)
                          : d->ground[c];
}

/* Fraction of texel (i, j) inside the disk (centre cd, cos radius cr). */
static double coverage(const hfs_sky_desc *d, int i, int j, const double cd[3], double r)
{
    const double w = d->width, h = d->height;
    const double e = 0.5 * M_PI - M_PI * (j + 0.5) / h, phi = 2.0 * M_PI * (i + 0.5) / w;
    const double px = fmax(M_PI / h, 2.0 * M_PI / w * cos(e)) * 0.75;
    if (fabs(e - asin(cd[2])) > r + px)
        return 0.0;
    const double ct = cos(e) * cos(phi) * cd[0] + cos(e) * sin(phi) * cd[1] + sin(e) * cd[2];
    if (ct < cos(fmin(r + px, M_PI)))
        return 0.0;
    if (r > px && ct > cos(r - px))
        return 1.0;
    int in = 0;
    const double cr = cos(r);
    for (int b = 0; b < SUB; ++b)
        for (int a = 0; a < SUB; ++a) {
            const double es = 0.5 * M_PI - M_PI * (j + (b + 0.5) / SUB) / h;
            const double ps = 2.0 * M_PI * (i + (a + 0.5) / SUB) / w;
            const double c =
                cos(es) * cos(ps) * cd[0] + cos(es) * sin(ps) * cd[1] + sin(es) * cd[2];
            in += c > cr;
        }
    return (double)in / (SUB * SUB);
}

int hfs_sky_render(const hfs_sky_desc *d, float *rgb, double (*energy)[3])
{
    const int w = d->width, h = d->height;
    if (w < 1 || h < 1 || d->n_disks < 0 || d->n_disks > HFS_SKY_MAX_DISKS)
        return -1;
    double cd[HFS_SKY_MAX_DISKS][3];
    for (int k = 0; k < d->n_disks; ++k) {
        const double p = d->disk[k].phi * DEG, e = d->disk[k].elev * DEG;
        cd[k][0] = cos(e) * cos(p);
        cd[k][1] = cos(e) * sin(p);
        cd[k][2] = sin(e);
        if (energy)
            energy[k][0] = energy[k][1] = energy[k][2] = 0.0;
    }
    for (int j = 0; j < h; ++j) {
        const double e = 0.5 * M_PI - M_PI * (j + 0.5) / h;
        const double dom = 2.0 * M_PI / w * (sin(0.5 * M_PI - M_PI * j / h) -
                                             sin(0.5 * M_PI - M_PI * (j + 1.0) / h));
        float base[3];
        sky_at(d, e, base);
        for (int i = 0; i < w; ++i) {
            float *p = rgb + ((size_t)j * w + i) * 3;
            const double f = d->noise > 0.0 ? 1.0 + d->noise * hash_unit(i, j, d->seed) : 1.0;
            for (int c = 0; c < 3; ++c)
                p[c] = (float)(base[c] * f);
            for (int k = 0; k < d->n_disks; ++k) {
                const double cov = coverage(d, i, j, cd[k], d->disk[k].radius * DEG);
                for (int c = 0; c < 3 && cov > 0.0; ++c) {
                    p[c] += (float)(d->disk[k].radiance[c] * cov);
                    if (energy)
                        energy[k][c] += d->disk[k].radiance[c] * cov * dom;
                }
            }
        }
    }
    return 0;
}

double hfs_sky_lum_energy(const float *rgb, int width, int height)
{
    double sum = 0.0;
    for (int j = 0; j < height; ++j) {
        const double dom = 2.0 * M_PI / width * (sin(0.5 * M_PI - M_PI * j / height) -
                                                 sin(0.5 * M_PI - M_PI * (j + 1.0) / height));
        double row = 0.0;
        for (int i = 0; i < width; ++i)
            row += lum(rgb + ((size_t)j * width + i) * 3);
        sum += row * dom;
    }
    return sum;
}

double hfs_sky_set_share(const hfs_sky_desc *d, int k, double share, float *rgb,
                         double (*energy)[3])
{
    /* Disk k holds E_k now; the rest is T - E_k.  Scale it by s so that
     * s E_k = share (T - E_k + s E_k). */
    const double t = hfs_sky_lum_energy(rgb, d->width, d->height);
    float one[3] = {(float)energy[k][0], (float)energy[k][1], (float)energy[k][2]};
    const double ek = lum(one);
    if (!(ek > 0.0) || !(share > 0.0 && share < 1.0))
        return 1.0;
    const double s = share * (t - ek) / ((1.0 - share) * ek);
    hfs_sky_desc one_disk = *d;
    one_disk.n_disks = 1;
    one_disk.disk[0] = d->disk[k];
    const double cdp = d->disk[k].phi * DEG, cde = d->disk[k].elev * DEG;
    const double cd[3] = {cos(cde) * cos(cdp), cos(cde) * sin(cdp), sin(cde)};
    for (int j = 0; j < d->height; ++j)
        for (int i = 0; i < d->width; ++i) {
            const double cov = coverage(&one_disk, i, j, cd, d->disk[k].radius * DEG);
            float *p = rgb + ((size_t)j * d->width + i) * 3;
            for (int c = 0; c < 3 && cov > 0.0; ++c)
                p[c] += (float)(d->disk[k].radiance[c] * cov * (s - 1.0));
        }
    for (int c = 0; c < 3; ++c)
        energy[k][c] *= s;
    return s;
}
