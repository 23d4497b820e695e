/*
 * objects.c — what stands above the field (objects.h).
 */
#include "objects.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "env_map_slices.h"
#include "env_open.h"
#include "field_geom.h"
#include "key_setup.h"
#include "lights.h"
#include "parallel.h"
#include "sh.h"
#include "slice_light.h"

#define PI 3.14159265358979323846

static const char *const kind_name[3] = {"point", "pin", "box"};

int hfs_objects_check(const hfs_field *f, const hfs_object *o, int n, hfs_error *err)
{
    if (n < 0 || n > HFS_MAX_OBJECTS || (n > 0 && !o))
        return hfs_fail(err, HFS_E_INVALID, "objects: %d of them (0..%d, with their array)", n,
                        HFS_MAX_OBJECTS);
    const double xmax = (f->width - 1) * f->dx, ymax = (f->height - 1) * f->dx;
    for (int i = 0; i < n; ++i) {
        const hfs_object *b = &o[i];
        if ((int)b->kind < 0 || (int)b->kind > HFS_OBJECT_BOX)
            return hfs_fail(err, HFS_E_INVALID, "object %d: unknown kind %d", i + 1,
                            (int)b->kind);
        const char *k = kind_name[b->kind];
        if (!(b->x >= 0.0 && b->x <= xmax && b->y >= 0.0 && b->y <= ymax))
            return hfs_fail(err, HFS_E_INVALID, "object %d (%s): (%g, %g) is off the field's "
                            "footprint [0, %g] x [0, %g]", i + 1, k, b->x, b->y, xmax, ymax);
        if (!(b->z >= 0.0 && b->z <= 1e12))
            return hfs_fail(err, HFS_E_INVALID, "object %d (%s): height above the surface %g "
                            "(0..1e12)", i + 1, k, b->z);
        const int sizes = b->kind == HFS_OBJECT_BOX ? 3 : b->kind == HFS_OBJECT_PIN ? 2 : 1;
        for (int s = 0; s < sizes; ++s) {
            const double v = b->kind == HFS_OBJECT_PIN && s == 1 ? b->size[2] : b->size[s];
            if (!(v > 0.0 && v <= 1e12))
                return hfs_fail(err, HFS_E_INVALID, "object %d (%s): size %g (must be in "
                                "(0, 1e12])", i + 1, k, v);
        }
        for (int c = 0; c < 3; ++c)
            if (!(b->albedo[c] >= 0.0f && b->albedo[c] <= 1.0f))
                return hfs_fail(err, HFS_E_INVALID, "object %d (%s): albedo %g (must be in "
                                "[0, 1])", i + 1, k, (double)b->albedo[c]);
    }
    return HFS_OK;
}

/* The surface's world height under (x, y) (on the footprint). */
static double ground(const hfs_field *f, double x, double y)
{
    double z = 0.0;
    hfs_field_bilinear(f, fmin(x / f->dx, f->width - 1.0), fmin(y / f->dx, f->height - 1.0), &z);
    return z;
}

int hfs_objects_make(const hfs_field *f, const hfs_object *o, int n, hfs_object_set *s,
                     hfs_error *err)
{
    memset(s, 0, sizeof *s);
    if (n == 0)
        return HFS_OK;
    s->box = malloc((size_t)n * sizeof *s->box);
    s->rgb = calloc((size_t)n * HFS_OBJ_FACE_VALUES, sizeof *s->rgb);
    s->albedo = malloc((size_t)n * sizeof *s->albedo);
    if (!s->box || !s->rgb || !s->albedo) {
        hfs_objects_free(s);
        return hfs_fail(err, HFS_E_NOMEM, "objects: out of memory");
    }
    s->n = n;
    for (int i = 0; i < n; ++i) {
        const hfs_object *b = &o[i];
        const double g = ground(f, b->x, b->y);
        double hw = 0.5 * b->size[0], hd = hw, z0 = g + b->z, z1;
        if (b->kind == HFS_OBJECT_BOX) {
            hd = 0.5 * b->size[1];
            z1 = z0 + b->size[2];
        } else if (b->kind == HFS_OBJECT_PIN) {
            z1 = z0 + b->size[2];
        } else { /* a point: a cube about its centre */
            z0 -= hw;
            z1 = z0 + b->size[0];
        }
        const double bx[6] = {b->x - hw, b->y - hd, z0, b->x + hw, b->y + hd, z1};
        memcpy(s->box[i], bx, sizeof bx);
        memcpy(s->albedo[i], b->albedo, sizeof s->albedo[i]);
    }
    return HFS_OK;
}

void hfs_objects_free(hfs_object_set *s)
{
    if (!s)
        return;
    free(s->box);
    free(s->rgb);
    free(s->albedo);
    memset(s, 0, sizeof *s);
}

/* Face `face`'s fixed axis, side and the two axes its grid runs along. */
static void face_axes(int face, int *fixed, int *hi, int *a0, int *a1)
{
    *fixed = face / 2;
    *hi = face % 2;
    *a0 = *fixed == 0 ? 1 : 0;
    *a1 = *fixed == 2 ? 1 : 2;
}

void hfs_objects_vertex(const hfs_object_set *s, int b, int face, int v, double p[3])
{
    int fixed, hi, a0, a1;
    face_axes(face, &fixed, &hi, &a0, &a1);
    const double *bx = s->box[b];
    const double u = (double)(v % (HFS_OBJ_GRID + 1)) / HFS_OBJ_GRID;
    const double w = (double)(v / (HFS_OBJ_GRID + 1)) / HFS_OBJ_GRID;
    p[fixed] = bx[fixed + 3 * hi];
    p[a0] = bx[a0] + u * (bx[a0 + 3] - bx[a0]);
    p[a1] = bx[a1] + w * (bx[a1 + 3] - bx[a1]);
}

static void face_normal(int face, double n[3])
{
    n[0] = n[1] = n[2] = 0.0;
    n[face / 2] = face % 2 ? 1.0 : -1.0;
}

void hfs_objects_query_points(const hfs_object_set *s, const hfs_field *f, double *xyz)
{
    const double lift = 1e-3 * f->dx;
    const double lim[2] = {(f->width - 1) * f->dx, (f->height - 1) * f->dx};
    for (int b = 0; b < s->n; ++b)
        for (int face = 0; face < 6; ++face) {
            double n[3];
            face_normal(face, n);
            for (int v = 0; v < HFS_OBJ_VERTS; ++v) {
                double *p = xyz + 3 * (((size_t)b * 6 + (size_t)face) * HFS_OBJ_VERTS + (size_t)v);
                hfs_objects_vertex(s, b, face, v, p);
                for (int k = 0; k < 3; ++k)
                    p[k] += lift * n[k];
                p[0] = fmin(fmax(p[0], 0.0), lim[0]);
                p[1] = fmin(fmax(p[1], 0.0), lim[1]);
            }
        }
}

/* What the environment's part needs, made once per lighting. */
typedef struct env_ctx {
    int on;
    hfs_slice_table t;
    hfs_map_slices ms;          /* env-shade = map on its own slices, or fg NULL */
    double l_env[3][HFS_SH_N];  /* rotated */
    double hz[HFS_ZH_N];
    const float *open;
    double rotate;
} env_ctx;

static void env_free(env_ctx *e)
{
    hfs_slice_table_free(&e->t);
    hfs_map_slices_free(&e->ms);
}

static int env_make(env_ctx *e, const hfs_lighting *l, const hfs_quality *q, hfs_error *err)
{
    memset(e, 0, sizeof *e);
    e->on = hfs_env_contributes(l);
    if (!e->on)
        return HFS_OK;
    hfs_swath sw; /* few points: more slices than the terrain's, cheaply */
    hfs_swath_full(q->nphi_env > HFS_OBJ_SLICES ? q->nphi_env : HFS_OBJ_SLICES, &sw);
    int rc = hfs_slice_table_init(&e->t, &sw, err);
    if (!rc && l->env_shade_map && l->env_open)
        rc = hfs_map_slices_build(&e->ms, l->env_shade_map, l->env_map_width, l->env_map_height,
                                  l->env_rotate, e->t.dir, e->t.n, e->t.dphi, err);
    hfs_env_rotated(l, e->l_env);
    hfs_zh_clamped_cosine(e->hz);
    e->open = l->env_open;
    e->rotate = l->env_rotate;
    if (rc)
        env_free(e);
    return rc;
}

/* The highest elevation of the terrain seen from p (world) toward the
 * slice direction (c, s), to the grid's edge; -pi/2 when nothing is there.
 * Half-texel steps to 16 texels, then steps of t / 32 (3% of the
 * distance, as the pyramid's octaves coarsen with distance); the highest
 * slope, one atan at the end. */
static double march_horizon(const hfs_field *f, const double p[3], double c, double s)
{
    const double gx = p[0] / f->dx, gy = p[1] / f->dx;
    double best = -INFINITY, z;
    for (double t = 0.5;; t += t < 16.0 ? 0.5 : t / 32.0) {
        if (!hfs_field_bilinear(f, gx + t * c, gy + t * s, &z))
            break;
        best = fmax(best, (z - p[2]) / (t * f->dx));
    }
    return best > -INFINITY ? atan(best) : -0.5 * PI;
}

/* The environment's irradiance at p for normal n (before albedo / pi). */
static void env_irradiance(const env_ctx *e, const hfs_field *f, const double p[3],
                           const double n[3], double out[3])
{
    double hn[HFS_SH_N], t[HFS_SH_N], d[3] = {0.0, 0.0, 0.0};
    hfs_sh_rotate_zonal(e->hz, n[0], n[1], n[2], hn);
    memcpy(t, hn, sizeof t);
    double occ[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j < e->t.n; ++j) {
        const double x = march_horizon(f, p, e->t.dir[2 * j], e->t.dir[2 * j + 1]);
        if (e->ms.fg)
            hfs_map_slices_occluded(&e->ms, j, n, x, occ);
        else
            hfs_slice_add_occluded(&e->t, j, n, x, t);
    }
    if (e->open)
        hfs_env_open_lookup(e->open, n, e->rotate, d);
    for (int c = 0; c < 3; ++c)
        out[c] = fmax(0.0, hfs_sh_dot(e->ms.fg ? hn : t, e->l_env[c]) + d[c] + occ[c]);
}

/* Key and local lights' irradiance at vertex p with normal n. */
static void lights_irradiance(const hfs_lighting *l, const double p[3], const double n[3],
                              const float *vis, double out[3])
{
    for (int k = 0; k < l->n_key; ++k) {
        const hfs_key_light *kl = &l->key[k];
        if (kl->disabled)
            continue;
        const double d[3] = {cos(kl->elev) * cos(kl->phi), cos(kl->elev) * sin(kl->phi),
                             sin(kl->elev)};
        const double e = hfs_cap_irradiance(n[0] * d[0] + n[1] * d[1] + n[2] * d[2], kl->alpha) *
                         vis[k];
        for (int c = 0; c < 3; ++c)
            out[c] += kl->radiance[c] * e;
    }
    for (int i = 0; i < l->n_local; ++i) {
        const hfs_local_light *ll = &l->local[i];
        if (ll->disabled)
            continue;
        const double v[3] = {ll->pos[0] - p[0], ll->pos[1] - p[1], ll->pos[2] - p[2]};
        const double dist = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(dist > 0.0))
            continue;
        const double alpha = dist > ll->radius ? asin(ll->radius / dist) : 0.5 * PI;
        const double e = hfs_cap_irradiance((n[0] * v[0] + n[1] * v[1] + n[2] * v[2]) / dist,
                                            alpha);
        for (int c = 0; c < 3; ++c)
            out[c] += ll->radiance[c] * e;
    }
}

typedef struct light_job {
    hfs_object_set *s;
    const hfs_field *f;
    const hfs_lighting *l;
    const env_ctx *e;
    const float *key_vis;
} light_job;

/* Object b's faces (a row of hfs_parallel_rows: objects are independent). */
static void light_object(void *ctx, int b, int worker)
{
    (void)worker;
    const light_job *j = ctx;
    hfs_object_set *s = j->s;
    for (int face = 0; face < 6; ++face) {
        if (face == 4)
            continue; /* the bottom: not lit, not drawn */
        double n[3];
        face_normal(face, n);
        for (int v = 0; v < HFS_OBJ_VERTS; ++v) {
            const size_t at = ((size_t)b * 6 + (size_t)face) * HFS_OBJ_VERTS + (size_t)v;
            double p[3], irr[3] = {0.0, 0.0, 0.0};
            hfs_objects_vertex(s, b, face, v, p);
            for (int k = 0; k < 3; ++k)
                p[k] += 1e-3 * j->f->dx * n[k];
            if (j->e->on)
                env_irradiance(j->e, j->f, p, n, irr);
            lights_irradiance(j->l, p, n, j->key_vis + at * (size_t)j->l->n_key, irr);
            for (int c = 0; c < 3; ++c)
                s->rgb[3 * at + (size_t)c] = (float)(s->albedo[b][c] * irr[c] / PI);
        }
    }
}

int hfs_objects_light(hfs_object_set *s, const hfs_field *f, const hfs_lighting *l,
                      const hfs_quality *q, const float *key_vis, hfs_error *err)
{
    env_ctx e;
    int rc = env_make(&e, l, q, err);
    if (rc)
        return rc;
    light_job j = {.s = s, .f = f, .l = l, .e = &e, .key_vis = key_vis};
    hfs_parallel_rows(s->n, q->threads, light_object, &j, NULL, NULL);
    env_free(&e);
    return HFS_OK;
}

void hfs_objects_face_rgb(const hfs_object_set *s, int b, int face, double u, double v,
                          double rgb[3])
{
    const double fu = fmin(fmax(u, 0.0), 1.0) * HFS_OBJ_GRID;
    const double fv = fmin(fmax(v, 0.0), 1.0) * HFS_OBJ_GRID;
    const int i = fu >= HFS_OBJ_GRID ? HFS_OBJ_GRID - 1 : (int)fu;
    const int j = fv >= HFS_OBJ_GRID ? HFS_OBJ_GRID - 1 : (int)fv;
    const double a = fu - i, c = fv - j;
    const float *g = s->rgb + ((size_t)b * 6 + (size_t)face) * HFS_OBJ_VERTS * 3;
    const int w = HFS_OBJ_GRID + 1;
    for (int k = 0; k < 3; ++k)
        rgb[k] = (1.0 - c) * ((1.0 - a) * g[3 * (j * w + i) + k] + a * g[3 * (j * w + i + 1) + k]) +
                 c * ((1.0 - a) * g[3 * ((j + 1) * w + i) + k] + a * g[3 * ((j + 1) * w + i + 1) + k]);
}
