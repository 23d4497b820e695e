/*
 * camera_env.c — see camera_env.h.
 */
#include "camera_env.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

struct hfs_camenv {
    hfs_camenv_params p;
    int fw, fh;                 /* the frame size the table is for (0: none) */
    int32_t *idx;               /* 4 pixels (y * fw + x) per texel; -1: unseen */
    float *wt;                  /* their bilinear weights                    */
    int *fill_row;              /* per output row: the row whose mean fills
                                   its unseen texels, -1: none seen at all   */
    float lut[256];             /* code -> linear radiance (x exposure)      */
};

void hfs_camenv_defaults(hfs_camenv_params *p)
{
    memset(p, 0, sizeof *p);
    p->mapping = HFS_MAP_MIRRORBALL;
    p->fov_deg = 180.0;
    p->exposure = 1.0;
    p->map_w = 256;
    p->map_h = 128;
    p->smoothing_s = 0.2;
    p->env_lights = -2;
}

const char *hfs_camenv_mapping_name(hfs_camenv_mapping m)
{
    return m == HFS_MAP_FISHEYE ? "fisheye" : m == HFS_MAP_EQUIRECT ? "equirect" : "mirrorball";
}

float hfs_camenv_decode(const hfs_camenv_params *p, int code)
{
    const double v = code / 255.0;
    if (p->linear)
        return (float)v;
    return (float)(v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4));
}

/* (v + 128) >> 8, clamped to 0..255 (the fixed-point form below). */
static int clamp8(int v)
{
    return v < 0 ? 0 : v >= 255 * 256 - 128 ? 255 : (v + 128) >> 8;
}

void hfs_camenv_yuv_to_rgb(int y, int cb, int cr, int rgb[3])
{
    /* BT.601 in 8.8 fixed point: 1.164 = 298/256, 1.596 = 409/256, 0.392
     * = 100/256, 0.813 = 208/256, 2.017 = 516/256. */
    const int l = 298 * (y - 16), u = cb - 128, v = cr - 128;
    rgb[0] = clamp8(l + 409 * v);
    rgb[1] = clamp8(l - 100 * u - 208 * v);
    rgb[2] = clamp8(l + 516 * u);
}

/* The circle mappings' frame: axis a, image right r and up u (world). */
static void basis(const hfs_camenv_params *p, double a[3], double r[3], double u[3])
{
    const double rot = p->rotate_deg * PI / 180.0;
    const double s = p->lower ? -1.0 : 1.0;
    a[0] = 0.0, a[1] = 0.0, a[2] = s;
    u[0] = cos(rot), u[1] = sin(rot), u[2] = 0.0;
    /* mirror ball: right = up x a; fisheye: a x up.  up x (0,0,s) =
     * (s u1, -s u0, 0). */
    const double m = p->mapping == HFS_MAP_MIRRORBALL ? s : -s;
    r[0] = m * u[1], r[1] = -m * u[0], r[2] = 0.0;
}

static void circle(const hfs_camenv_params *p, int w, int h, double *cx, double *cy, double *rad)
{
    *cx = p->has_center ? p->cx : 0.5 * w;
    *cy = p->has_center ? p->cy : 0.5 * h;
    *rad = p->radius > 0.0 ? p->radius : 0.5 * (w < h ? w : h);
}

int hfs_camenv_pixel_to_dir(const hfs_camenv_params *p, int w, int h, double x, double y,
                            double d[3])
{
    if (p->mapping == HFS_MAP_EQUIRECT) {
        const double phi = p->rotate_deg * PI / 180.0 + 2.0 * PI * x / w;
        const double e = 0.5 * PI - PI * y / h;
        d[0] = cos(phi) * cos(e), d[1] = sin(phi) * cos(e), d[2] = sin(e);
        return 1;
    }
    double cx, cy, rad, a[3], r[3], u[3];
    circle(p, w, h, &cx, &cy, &rad);
    basis(p, a, r, u);
    const double dx = (x - cx) / rad, dy = (cy - y) / rad;
    const double rho = sqrt(dx * dx + dy * dy);
    if (rho > 1.0)
        return 0;
    const double th = p->mapping == HFS_MAP_MIRRORBALL ? 2.0 * asin(rho)
                                                       : rho * 0.5 * p->fov_deg * PI / 180.0;
    const double c = rho > 0.0 ? dx / rho : 1.0, s = rho > 0.0 ? dy / rho : 0.0;
    for (int k = 0; k < 3; ++k)
        d[k] = cos(th) * a[k] + sin(th) * (c * r[k] + s * u[k]);
    return 1;
}

int hfs_camenv_dir_to_pixel(const hfs_camenv_params *p, int w, int h, const double d[3],
                            double *x, double *y)
{
    if (p->mapping == HFS_MAP_EQUIRECT) {
        double phi = atan2(d[1], d[0]) - p->rotate_deg * PI / 180.0;
        phi = fmod(phi, 2.0 * PI);
        if (phi < 0.0)
            phi += 2.0 * PI;
        const double e = asin(fmax(-1.0, fmin(1.0, d[2])));
        *x = phi / (2.0 * PI) * w;
        *y = (0.5 * PI - e) / PI * h;
        return 1;
    }
    double cx, cy, rad, a[3], r[3], u[3];
    circle(p, w, h, &cx, &cy, &rad);
    basis(p, a, r, u);
    const double ca = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
    const double th = acos(fmax(-1.0, fmin(1.0, ca)));
    const double sx = d[0] * r[0] + d[1] * r[1] + d[2] * r[2];
    const double sy = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    const double rho = p->mapping == HFS_MAP_MIRRORBALL ? sin(0.5 * th)
                                                        : th / (0.5 * p->fov_deg * PI / 180.0);
    if (rho > 1.0)
        return 0;
    const double psi = atan2(sy, sx);
    *x = cx + rho * rad * cos(psi);
    *y = cy - rho * rad * sin(psi);
    return *x >= 0.0 && *y >= 0.0 && *x <= w && *y <= h;
}

int hfs_camenv_create(const hfs_camenv_params *p, hfs_camenv **out, hfs_error *err)
{
    *out = NULL;
    if (p->map_w < 16 || p->map_h < 8 || p->map_w > 4096 || p->map_h > 2048)
        return hfs_fail(err, HFS_E_INVALID, "environment map %dx%d: not 16x8..4096x2048",
                        p->map_w, p->map_h);
    hfs_camenv *c = calloc(1, sizeof *c);
    if (!c)
        return hfs_fail(err, HFS_E_NOMEM, "camera environment: out of memory");
    c->p = *p;
    for (int i = 0; i < 256; ++i)
        c->lut[i] = (float)(hfs_camenv_decode(p, i) * p->exposure);
    *out = c;
    return HFS_OK;
}

void hfs_camenv_destroy(hfs_camenv *c)
{
    if (!c)
        return;
    free(c->idx);
    free(c->wt);
    free(c->fill_row);
    free(c);
}

/* Texel t's 4 pixels and weights for the frame point (x, y). */
static void bilinear(const hfs_camenv *c, double x, double y, int32_t *idx, float *wt)
{
    const int w = c->fw, h = c->fh, wrap = c->p.mapping == HFS_MAP_EQUIRECT;
    const double fx = x - 0.5, fy = y - 0.5;
    const int x0 = (int)floor(fx), y0 = (int)floor(fy);
    const double tx = fx - x0, ty = fy - y0;
    for (int k = 0; k < 4; ++k) {
        int xi = x0 + (k & 1), yi = y0 + (k >> 1);
        if (wrap)
            xi = ((xi % w) + w) % w;
        xi = xi < 0 ? 0 : xi >= w ? w - 1 : xi;
        yi = yi < 0 ? 0 : yi >= h ? h - 1 : yi;
        idx[k] = (int32_t)yi * w + xi;
        wt[k] = (float)(((k & 1) ? tx : 1.0 - tx) * ((k >> 1) ? ty : 1.0 - ty));
    }
}

/* Each row's fill source: the nearest row with a seen texel (below first
 * on a tie), -1 when none is seen. */
static void fill_rows(hfs_camenv *c, const int *seen)
{
    const int H = c->p.map_h;
    for (int j = 0; j < H; ++j) {
        c->fill_row[j] = -1;
        for (int k = 0; k < H && c->fill_row[j] < 0; ++k) {
            if (j + k < H && seen[j + k])
                c->fill_row[j] = j + k;
            else if (j - k >= 0 && seen[j - k])
                c->fill_row[j] = j - k;
        }
    }
}

static int build(hfs_camenv *c, int fw, int fh, hfs_error *err)
{
    const int W = c->p.map_w, H = c->p.map_h;
    const size_t n = (size_t)W * H * 4;
    free(c->idx), free(c->wt), free(c->fill_row);
    c->idx = malloc(n * sizeof *c->idx);
    c->wt = malloc(n * sizeof *c->wt);
    c->fill_row = malloc((size_t)H * sizeof *c->fill_row);
    int *seen = calloc((size_t)H, sizeof *seen);
    if (!c->idx || !c->wt || !c->fill_row || !seen) {
        free(seen);
        c->fw = 0;
        return hfs_fail(err, HFS_E_NOMEM, "camera environment: out of memory");
    }
    c->fw = fw, c->fh = fh;
    for (int j = 0; j < H; ++j) {
        const double e = 0.5 * PI - PI * (j + 0.5) / H;
        for (int i = 0; i < W; ++i) {
            const double phi = 2.0 * PI * (i + 0.5) / W;
            const double d[3] = {cos(phi) * cos(e), sin(phi) * cos(e), sin(e)};
            const size_t t = ((size_t)j * W + i) * 4;
            double x, y;
            if (hfs_camenv_dir_to_pixel(&c->p, fw, fh, d, &x, &y)) {
                bilinear(c, x, y, c->idx + t, c->wt + t);
                seen[j] = 1;
            } else {
                c->idx[t] = -1;
            }
        }
    }
    fill_rows(c, seen);
    free(seen);
    return HFS_OK;
}

/* Linear RGB of pixel i (y * w + x) of the frame. */
static void pixel(const hfs_camenv *c, const hfs_capture_frame *f, int32_t i, float rgb[3])
{
    const int x = i % f->width, y = i / f->width;
    const uint8_t *row = f->data + (size_t)y * f->stride;
    if (f->format == HFS_PIX_GREY) {
        rgb[0] = rgb[1] = rgb[2] = c->lut[row[x]];
        return;
    }
    const uint8_t *q = row + 4 * (x / 2);
    int v[3];
    hfs_camenv_yuv_to_rgb(row[2 * x], q[1], q[3], v);
    for (int k = 0; k < 3; ++k)
        rgb[k] = c->lut[v[k]];
}

/* Unseen texels: their fill row's mean of seen texels. */
static void fill_unseen(const hfs_camenv *c, float *map)
{
    const int W = c->p.map_w, H = c->p.map_h;
    float *mean = calloc((size_t)H * 3, sizeof *mean);
    if (!mean) { /* cannot happen at these sizes; black is a safe answer */
        for (size_t t = 0; t < (size_t)W * H; ++t)
            if (c->idx[t * 4] < 0)
                map[t * 3] = map[t * 3 + 1] = map[t * 3 + 2] = 0.0f;
        return;
    }
    for (int j = 0; j < H; ++j) {
        double s[3] = {0, 0, 0};
        int n = 0;
        for (int i = 0; i < W; ++i) {
            const size_t t = (size_t)j * W + i;
            if (c->idx[t * 4] < 0)
                continue;
            ++n;
            for (int k = 0; k < 3; ++k)
                s[k] += map[t * 3 + k];
        }
        for (int k = 0; k < 3 && n; ++k)
            mean[j * 3 + k] = (float)(s[k] / n);
    }
    for (int j = 0; j < H; ++j) {
        const int src = c->fill_row[j];
        for (int i = 0; i < W; ++i) {
            const size_t t = (size_t)j * W + i;
            if (c->idx[t * 4] >= 0)
                continue;
            for (int k = 0; k < 3; ++k)
                map[t * 3 + k] = src < 0 ? 0.0f : mean[src * 3 + k];
        }
    }
    free(mean);
}

int hfs_camenv_convert(hfs_camenv *c, const hfs_capture_frame *f, float *map, hfs_error *err)
{
    if (f->format != HFS_PIX_GREY && f->format != HFS_PIX_YUYV)
        return hfs_fail(err, HFS_E_FORMAT, "%s frames are not an environment (GREY or YUYV)",
                        hfs_pixfmt_name(f->format) ? hfs_pixfmt_name(f->format) : "these");
    if (f->width < 2 || f->height < 2)
        return hfs_fail(err, HFS_E_FORMAT, "a %dx%d frame is too small", f->width, f->height);
    int rc;
    if ((f->width != c->fw || f->height != c->fh) && (rc = build(c, f->width, f->height, err)))
        return rc;
    const size_t n = (size_t)c->p.map_w * c->p.map_h;
    for (size_t t = 0; t < n; ++t) {
        const int32_t *id = c->idx + t * 4;
        const float *wt = c->wt + t * 4;
        float acc[3] = {0, 0, 0};
        for (int k = 0; k < 4 && id[0] >= 0; ++k) {
            float px[3];
            pixel(c, f, id[k], px);
            for (int q = 0; q < 3; ++q)
                acc[q] += wt[k] * px[q];
        }
        memcpy(map + t * 3, acc, sizeof acc);
    }
    fill_unseen(c, map);
    return HFS_OK;
}
