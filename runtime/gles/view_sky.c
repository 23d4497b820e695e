/*
 * view_sky.c — see view_sky.h.
 */
#include "view_sky.h"

#include "gl_util.h"
#include "half.h"
#include "resources.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int hfs_gles_view_sky_wanted(const hfs_camera *cam, const hfs_lighting *l)
{
    return cam->look.background == HFS_BACKGROUND_SKY && l->has_env && l->env_map != NULL;
}

void hfs_gles_view_sky_free(hfs_gles_view_sky *s, const hfs_gl *gl)
{
    hfs_gles_tex_delete(gl, &s->tex);
    s->map = NULL;
}

/* *w x *h RGB halved (2 x 2 box means; an odd last row or column is
 * averaged with itself) in place. */
static void halve(double *rgb, int *w, int *h)
{
    const int nw = (*w + 1) / 2, nh = (*h + 1) / 2;
    for (int r = 0; r < nh; ++r)
        for (int q = 0; q < nw; ++q)
            for (int c = 0; c < 3; ++c) {
                const int r0 = 2 * r, r1 = 2 * r + 1 < *h ? 2 * r + 1 : 2 * r;
                const int q0 = 2 * q, q1 = 2 * q + 1 < *w ? 2 * q + 1 : 2 * q;
                const double v = rgb[3 * ((size_t)r0 * *w + q0) + c] +
                                 rgb[3 * ((size_t)r0 * *w + q1) + c] +
                                 rgb[3 * ((size_t)r1 * *w + q0) + c] +
                                 rgb[3 * ((size_t)r1 * *w + q1) + c];
                rgb[3 * ((size_t)r * nw + q) + c] = 0.25 * v; /* never ahead of the reads */
            }
    *w = nw, *h = nh;
}

/* rgb (w x h) times s as RGBA into a new texture *tex. */
static int upload(hfs_gles_view_sky *s, const hfs_gl *gl, const hfs_gl_caps *c,
                  const double *rgb, int w, int h, double scale, hfs_error *err)
{
    const size_t n = (size_t)w * (size_t)h;
    void *buf = malloc(n * 4 * (c->fp32 ? sizeof(float) : sizeof(uint16_t)));
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the view's sky");
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 4; ++k) {
            const float v = k < 3 ? (float)(rgb[3 * i + (size_t)k] * scale) : 0.0f;
            if (c->fp32)
                ((float *)buf)[4 * i + (size_t)k] = v;
            else
                ((uint16_t *)buf)[4 * i + (size_t)k] = hfs_float_to_half(v);
        }
    s->tex = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D, s->tex);
    gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, c->type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    free(buf);
    return hfs_gl_check(gl, "backend gles: the view's sky", err);
}

int hfs_gles_view_sky_follow(hfs_gles_view_sky *s, const hfs_gl *gl, const hfs_gl_caps *c,
                             const hfs_lighting *l, hfs_error *err)
{
    if (s->tex && s->map == l->env_map && s->map_w == l->env_map_width &&
        s->map_h == l->env_map_height && s->fp32 == c->fp32 &&
        !memcmp(s->sh, l->env_sh, sizeof s->sh))
        return HFS_OK;
    hfs_gles_view_sky_free(s, gl);
    int w = l->env_map_width, h = l->env_map_height;
    double *rgb = malloc((size_t)w * (size_t)h * 3 * sizeof *rgb);
    if (!rgb)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the view's sky");
    double mx = 0.0;
    for (size_t i = 0; i < (size_t)w * (size_t)h * 3; ++i) {
        rgb[i] = l->env_map[i];
        mx = fmax(mx, fabs(rgb[i]));
    }
    while (w > c->max_texture_size || h > c->max_texture_size)
        halve(rgb, &w, &h);
    /* A power of two: exact, and the largest value lands at 2^15. */
    const double scale = mx > 0.0 ? ldexp(1.0, 15 - (int)ceil(log2(mx))) : 1.0;
    const int rc = upload(s, gl, c, rgb, w, h, scale, err);
    free(rgb);
    if (rc) {
        hfs_gles_view_sky_free(s, gl);
        return rc;
    }
    s->map = l->env_map, s->map_w = l->env_map_width, s->map_h = l->env_map_height;
    s->fp32 = c->fp32;
    memcpy(s->sh, l->env_sh, sizeof s->sh);
    s->mul = 1.0 / scale;
    s->max = mx;
    return HFS_OK;
}

double hfs_gles_view_look_bound(const hfs_camera *cam, const hfs_gles_view_sky *s, int map)
{
    const hfs_view_look *k = &cam->look;
    double b = map ? s->max : 0.0;
    const double top = k->background == HFS_BACKGROUND_STUDIO
                           ? HFS_STUDIO_BASE + 2.0 * HFS_STUDIO_SLOPE
                           : 1.0;
    for (int c = 0; c < 3 && k->background != HFS_BACKGROUND_SKY; ++c)
        b = fmax(b, k->rgb[c] * top);
    return b;
}

void hfs_gles_view_look_fill(hfs_gles_view_block *b, const hfs_camera *cam,
                             const hfs_lighting *l, const hfs_gles_view_sky *s, int map,
                             double scale)
{
    const hfs_view_look *k = &cam->look;
    b->bg[0] = k->background == HFS_BACKGROUND_COLOR    ? 3.0f
               : k->background == HFS_BACKGROUND_STUDIO ? 2.0f
               : map                                    ? 1.0f
                                                        : 0.0f;
    b->bg[1] = map ? (float)(s->mul * scale) : 0.0f;
    b->bg[2] = (float)fmod(l->env_rotate, 2.0 * 3.14159265358979323846); /* float keeps it */
    for (int c = 0; c < 3; ++c) {
        b->bg_rgb[c] = (float)(k->rgb[c] * scale);
        b->haze_in[c] = (float)(k->in[c] * scale);
    }
    b->haze[0] = (float)k->sigma;
    b->haze[1] = (float)k->z0;
    b->haze[2] = (float)(k->sigma > 0.0 ? k->scale_h : 1.0);
}
