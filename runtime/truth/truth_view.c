/*
 * truth_view.c — see truth_view.h.
 */
#include "truth_view.h"

#include "field_geom.h"
#include "parallel.h"
#include "sh.h"
#include "truth_raycast.h"

#include <math.h>

typedef struct view_ctx {
    const hfs_field *f;       /* exaggerated copy's view */
    const hfs_truth_grid *g;
    const float *lit;
    const hfs_camera_frame *fr;
    double base;              /* the block's bottom: the lowest height (world z) */
    double env[3][HFS_SH_N];
    int w, h;
    float *view;
    const hfs_object_set *obj; /* in the view's world (z exaggerated), or NULL */
    const hfs_lighting *l;     /* the sky background's map */
    const hfs_view_look *look; /* background and haze (view_look.h) */
} view_ctx;

/* rgb as seen through the haze at distance dist along the ray from org
 * (unit direction d); nothing to do with the haze off, so such a view is
 * the one without it bit for bit. */
static void seen(const view_ctx *v, const double org[3], const double d[3], double dist,
                 const double lo[3], float *rgb)
{
    double x[3] = {lo[0], lo[1], lo[2]};
    if (v->look->sigma > 0.0)
        hfs_haze_apply(v->look, dist, org[2], org[2] + dist * d[2], x);
    for (int c = 0; c < 3; ++c)
        rgb[c] = (float)x[c];
}

/* The nearest object the ray org + t d (t in (0, tmax)) meets: its index,
 * or -1; *t, the face and its (u, v) (objects.h conventions). */
static int object_hit(const hfs_object_set *s, const double org[3], const double d[3],
                      double tmax, double *t, int *face, double uv[2])
{
    int best = -1;
    for (int b = 0; s && b < s->n; ++b) {
        const double *bx = s->box[b];
        double lo = 0.0, hi = tmax;
        int axis = -1, side = 0;
        for (int a = 0; a < 3 && lo <= hi; ++a) {
            if (d[a] == 0.0) {
                if (org[a] < bx[a] || org[a] > bx[a + 3])
                    hi = -1.0;
                continue;
            }
            double t0 = (bx[a] - org[a]) / d[a], t1 = (bx[a + 3] - org[a]) / d[a];
            const int s0 = t0 > t1;
            if (s0) {
                const double x = t0;
                t0 = t1, t1 = x;
            }
            if (t0 > lo)
                lo = t0, axis = a, side = s0; /* entered through the far-coordinate side */
            hi = fmin(hi, t1);
        }
        if (lo > hi || axis < 0 || !(lo > 0.0) || lo >= tmax)
            continue;
        tmax = lo;
        best = b;
        *t = lo;
        *face = 2 * axis + side;
        const int a0 = axis == 0 ? 1 : 0, a1 = axis == 2 ? 1 : 2;
        uv[0] = (org[a0] + lo * d[a0] - bx[a0]) / (bx[a0 + 3] - bx[a0]);
        uv[1] = (org[a1] + lo * d[a1] - bx[a1]) / (bx[a1 + 3] - bx[a1]);
    }
    return best;
}

/* The parameter range [t0, t1] in which the ray's xy lies inside the
 * grid's rectangle [0, W-1] x [0, H-1] (grid units); 0 when it never does. */
static int grid_span(const hfs_field *f, const double o[2], const double d[2], double *t0,
                     double *t1)
{
    double lo = 0.0, hi = INFINITY;
    const double lim[2] = {f->width - 1.0, f->height - 1.0};
    for (int a = 0; a < 2; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < 0.0 || o[a] > lim[a])
                return 0;
            continue;
        }
        double ta = (0.0 - o[a]) / d[a], tb = (lim[a] - o[a]) / d[a];
        if (ta > tb) {
            const double t = ta;
            ta = tb, tb = t;
        }
        lo = fmax(lo, ta), hi = fmin(hi, tb);
    }
    *t0 = lo, *t1 = hi;
    return lo <= hi;
}

static void shade_pixel(const view_ctx *v, int px, int py, float *rgb)
{
    const hfs_field *f = v->f;
    double d[3], org[3];
    hfs_camera_ray_at(v->fr, v->w, v->h, px, py, org, d);
    /* The ray in grid units for xy, world for z and t. */
    const double og[2] = {org[0] / f->dx, org[1] / f->dx};
    const double dg[2] = {d[0] / f->dx, d[1] / f->dx};
    double t0 = 1.0, t1 = 0.0, t, tobj = 0.0, uv[2] = {0.0, 0.0}; /* t0 > t1: no crossing */
    int face = 0;
    const int ob = object_hit(v->obj, org, d, INFINITY, &tobj, &face, uv);
    /* The field is a block down to its lowest height: a ray below that
     * enters it, if at all, through the bottom (rising). */
    if (grid_span(f, og, dg, &t0, &t1) && org[2] + t0 * d[2] < v->base)
        t0 = d[2] > 0.0 ? (v->base - org[2]) / d[2] : INFINITY;
    if (t0 <= t1) {
        /* Start just inside the rectangle: the ray tests need an origin
         * in the grid. */
        const double ts = t0 + 1e-9 * (1.0 + t0);
        const double o[3] = {fmin(fmax(og[0] + ts * dg[0], 0.0), f->width - 1.0),
                             fmin(fmax(og[1] + ts * dg[1], 0.0), f->height - 1.0),
                             org[2] + ts * d[2]};
        if (ts <= t1 && hfs_truth_ray_first_hit(v->g, o, d, INFINITY, &t) &&
            (ob < 0 || ts + t < tobj)) {
            double lo[3];
            hfs_rgb_bilinear(v->lit, f->width, f->height, o[0] + t * dg[0], o[1] + t * dg[1],
                             lo);
            seen(v, org, d, ts + t, lo, rgb);
            return;
        }
    }
    if (ob >= 0) { /* an object in front of the terrain, or over the sky */
        double lo[3];
        hfs_objects_face_rgb(v->obj, ob, face, uv[0], uv[1], lo);
        seen(v, org, d, tobj, lo, rgb);
        return;
    }
    double bg[3];
    hfs_view_background(v->look, v->l, v->env, d, bg);
    for (int c = 0; c < 3; ++c)
        rgb[c] = (float)bg[c];
}

static void view_row(void *ctx, int py, int worker)
{
    (void)worker;
    const view_ctx *v = ctx;
    for (int px = 0; px < v->w; ++px)
        shade_pixel(v, px, py, v->view + 3 * ((size_t)py * (size_t)v->w + (size_t)px));
}

int hfs_truth_view(const hfs_field *f, const float *lit, const hfs_lighting *l,
                   const hfs_camera *cam, const hfs_object_set *obj, int w, int h, float *view,
                   int threads, hfs_error *err)
{
    /* The view's terrain: the same heights, zscale times the exaggeration. */
    const hfs_field fe = {f->width, f->height, f->z, f->dx, f->zscale * cam->exaggeration};
    hfs_truth_grid g;
    if (hfs_truth_grid_init(&g, &fe) != HFS_OK)
        return hfs_fail(err, HFS_E_NOMEM, "truth view: out of memory for the height tree");
    hfs_camera_frame fr;
    hfs_camera_frame_make(cam, &fr);
    double lo, hi;
    hfs_field_range(&fe, &lo, &hi);
    view_ctx v = {.f = &fe, .g = &g, .lit = lit, .fr = &fr, .w = w,
                  .h = h, .view = view, .base = lo * fe.zscale, .obj = obj, .l = l,
                  .look = &cam->look};
    for (int c = 0; c < 3 && l->has_env; ++c)
        hfs_sh_rotate_z(l->env_sh[c], l->env_rotate, v.env[c]);
    hfs_parallel_rows(h, threads, view_row, &v, NULL, NULL);
    hfs_truth_grid_free(&g);
    return HFS_OK;
}
