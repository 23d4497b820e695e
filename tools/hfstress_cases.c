/*
 * hfstress_cases.c — the stress case table and the scenes it builds
 * (hfstress.h; docs/STRESS.md lists every case and why it is there).
 *
 * A case is a terrain (generator, size, relief rescale, dx, zscale, holes),
 * a lighting preset and the expected outcome.  Lights are placed from the
 * field's world extent at s = 1 and then scaled, so the scaled scene of the
 * invariance check is the same scene in other units: dx, zscale, local
 * positions and radii all multiplied by s, heights and angles unchanged.
 */
#include "hfstress.h"

#include "hfs_io.h"
#include "sh.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define NODATA (-32768.0f)

/* Invariance factors of most cases: three orders of magnitude both ways. */
#define SCALES {1e-3, 1e3}
#define NO_SCALES {0.0, 0.0}

/* clang-format off */
static const stress_case cases[] = {
    /* Relief and spacing. */
    {"relief_1e-6", "fractal 64x64, heights 0..1e-6 world units (dx 1)", 1,
     64, 64, TER_FRACTAL, 1e-6, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"relief_1e5", "fractal 64x64, heights 0..1e5 (dx 1: slopes ~1e4)", 1,
     64, 64, TER_FRACTAL, 1e5, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 1},
    {"relief_1e5_dx1e3", "fractal 128x96, heights 0..1e5 at dx 1e3", 0,
     128, 96, TER_FRACTAL, 1e5, 1e3, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"dx_1e-6", "fractal 64x64 (texel-unit heights) at dx 1e-6: walls", 1,
     64, 64, TER_FRACTAL, 0.0, 1e-6, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"dx_1e6", "the same heights at dx 1e6: nearly flat", 0,
     48, 40, TER_FRACTAL, 0.0, 1e6, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"scale_1e-6_1e6", "cones 64x64, invariance under s = 1e-6 and 1e6", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, {1e-6, 1e6}, 0, 0},
    {"zscale_0", "fractal 64x64 at zscale 0 under the uniform sky: exactly 1", 1,
     64, 64, TER_FRACTAL, 0.0, 1.0, 0.0, HOLES_NONE, LIGHT_SKY_UNIFORM, 0, EXPECT_RENDER, 1.0, SCALES, 0, 0},
    {"zscale_0_lights", "fractal 64x64 at zscale 0, uniform sky + sun + local light: U", 0,
     64, 64, TER_FRACTAL, 0.0, 1.0, 0.0, HOLES_NONE, LIGHT_STD_UNIFORM, 0, EXPECT_RENDER,
     STRESS_EXPECT_U, SCALES, 0, 1},
    {"flat_tiny_lights", "flat 64x64, uniform sky, a 1e-8 rad sun and local light: U", 1,
     64, 64, TER_FLAT, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_TINY, 0, EXPECT_RENDER, STRESS_EXPECT_U,
     SCALES, 0, 0},

    /* Sizes. */
    {"size_2x2", "the smallest field, hashed heights", 1,
     2, 2, TER_RANDOM, 1.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 1, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"size_1x4096", "one column: below SPEC's 2x2 minimum, refused", 1,
     1, 4096, TER_RAMP, 10.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 1, EXPECT_REFUSE, -1, NO_SCALES, 0, 0},
    /* in the fast subset: the ES 3.0 profiles' refusal of it (naming
     * GL_MAX_TEXTURE_SIZE) changed with the tiled renders unseen */
    {"size_2x4096", "two columns of 4096 rows", 1,
     2, 4096, TER_FRACTAL, 64.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"size_4096x2", "4096 columns, two rows", 0,
     4096, 2, TER_FRACTAL, 64.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"npot_37x61", "odd, non-power-of-two sides", 1,
     37, 61, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"npot_3x5", "3x5 hashed heights", 1,
     3, 5, TER_RANDOM, 2.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 1, EXPECT_RENDER, -1, SCALES, 0, 1},
    {"npot_129x2", "a 129x2 ramp", 1,
     129, 2, TER_RAMP, 8.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"npot_257x255", "one past and one short of a power of two", 0,
     257, 255, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},

    /* Holes. */
    {"holes_raw_nan", "a NaN height handed to the renderer: refused", 1,
     32, 32, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_RAW, LIGHT_STD, 1, EXPECT_REFUSE, -1, NO_SCALES, 0, 0},
    {"holes_raw_inf", "+Inf and -Inf heights handed to the renderer: refused", 1,
     32, 32, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_RAW_INF, LIGHT_STD, 0, EXPECT_REFUSE, -1, NO_SCALES, 0, 0},
    {"holes_filled", "NaN, +-Inf, nodata and a 6x6 hole filled by push-pull", 1,
     64, 64, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_FILLED, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},

    {"size_2x2048", "two columns at ES 3.0's texture limit", 0,
     2, 2048, TER_FRACTAL, 64.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"size_2048x2", "two rows at ES 3.0's texture limit", 0,
     2048, 2, TER_FRACTAL, 64.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},

    /* A single spike. */
    {"spike_1e5", "flat 64x64 but one texel at 1e5 (dx 1)", 1,
     64, 64, TER_SPIKE, 1e5, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"spike_17x17", "flat 17x17 but one texel at 4, against the truth", 0,
     17, 17, TER_SPIKE, 4.0, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 1, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"sun_ramp_spike_1e5", "a ramp at the sun's elevation (all penumbra) by a 1e5 spike", 0,
     64, 64, TER_SUN_RAMP, 1e5, 1.0, 1.0, HOLES_NONE, LIGHT_STD, 0, EXPECT_RENDER, -1, SCALES, 0, 0},

    /* Key lights. */
    {"key_zenith", "a 2-degree key light straight up (full swath)", 1,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_ZENITH, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"key_horizon", "a key light centred on the horizon", 1,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_HORIZON, 0, EXPECT_RENDER, -1, SCALES, 0, 1},
    {"key_below", "a key light 11 degrees below the horizon", 1,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_BELOW, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"key_nadir", "a key light straight down", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_NADIR, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"key_huge", "a key disk of angular radius 1.5 rad", 1,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_HUGE, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"key_grazing_1e-8", "a 1e-8 rad sun in the plane of a 9x9 ramp, against the truth", 1,
     9, 9, TER_SUN_RAMP, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_GRAZING, 1, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"key_tiny", "a key disk of angular radius 1e-5 rad", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_TINY, 0, EXPECT_RENDER, -1, SCALES, 0, 0},

    /* Local lights. */
    {"local_buried", "local lights inside a cone, under the field, across the surface", 1,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_LOCAL_BURIED, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"local_r0", "a local light of radius 0 (a point: no light)", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_LOCAL_R0, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"local_huge_inside", "a sphere 100x the field around it: rho Le everywhere", 1,
     64, 64, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_LOCAL_HUGE_IN, 0, EXPECT_RENDER, 2.0, SCALES, 0, 0},
    {"local_huge_outside", "a sphere of twice the field's size above it", 0,
     64, 64, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_LOCAL_HUGE_OUT, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"local_zenith", "a light over a grid point, and one centred on a receiver", 1,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_LOCAL_ZENITH, 0, EXPECT_RENDER, -1, SCALES, 0, 1},
    {"local_horizon", "a light level with the terrain, far off the grid", 0,
     64, 64, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_LOCAL_HORIZON, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"local_below", "a light below the terrain, beside the grid", 0,
     64, 64, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_LOCAL_BELOW, 0, EXPECT_RENDER, -1, SCALES, 0, 0},

    /* The SN08 wedge-table path (no local lights there on GLES). */
    {"tables_relief_1e5", "wedge tables: relief 0..1e5 under a horizon sun", 0,
     64, 64, TER_FRACTAL, 1e5, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_HORIZON, 0, EXPECT_RENDER, -1, SCALES, 1, 0},
    {"tables_key_zenith", "wedge tables: a key light straight up", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_KEY_ZENITH, 0, EXPECT_RENDER, -1, SCALES, 1, 1},
    {"tables_env_hot", "wedge tables: the hot pixel below the horizon", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_ENV_HOT_BELOW, 0, EXPECT_RENDER, -1, SCALES, 1, 0},

    /* Radiance. */
    {"radiance_0", "every light kind present with radiance 0: exactly 0", 1,
     64, 64, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_RADIANCE_0, 0, EXPECT_RENDER, 0.0, SCALES, 0, 0},
    {"radiance_1e6", "sky, sun and local light at radiance 1e6", 1,
     64, 64, TER_FRACTAL, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_RADIANCE_1E6, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"radiance_mixed", "a 1e6 sun over a sky of 1", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_MIXED_1E6, 0, EXPECT_RENDER, -1, SCALES, 0, 0},

    /* Environment maps with one hot pixel. */
    {"env_hot_zenith", "equirect 64x32, 0 but one 1e5 pixel at the zenith", 1,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_ENV_HOT_ZENITH, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"env_hot_horizon", "the hot pixel just above the horizon", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_ENV_HOT_HORIZON, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
    {"env_hot_below", "the hot pixel below the horizon", 0,
     64, 64, TER_CONES, 0.0, 1.0, 1.0, HOLES_NONE, LIGHT_ENV_HOT_BELOW, 0, EXPECT_RENDER, -1, SCALES, 0, 0},
};
/* clang-format on */

const stress_case *stress_cases(int *count)
{
    *count = (int)(sizeof cases / sizeof cases[0]);
    return cases;
}

const stress_case *stress_case_find(const char *name)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        if (!strcmp(cases[i].name, name))
            return &cases[i];
    return NULL;
}

/* ---- terrain ---------------------------------------------------------------------- */

/* Integer hash to [0, 1): deterministic on every machine. */
static double hash01(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return (double)(x >> 8) / 16777216.0;
}

static int make_terrain(const stress_case *c, float *z)
{
    const int w = c->w, h = c->h;
    const size_t n = (size_t)w * (size_t)h;
    switch (c->terrain) {
    case TER_FRACTAL:
        /* The generator wants 2x2 at least; relief 0.25 of the smaller side. */
        if (hfs_terrain_fractal(z, w, h, 7, 0.25))
            return -1;
        break;
    case TER_CONES:
        hfs_terrain_cones(z, w, h);
        break;
    case TER_FLAT:
        memset(z, 0, n * sizeof *z);
        break;
    case TER_SPIKE:
        memset(z, 0, n * sizeof *z);
        z[(size_t)(h / 2) * (size_t)w + (size_t)(w / 2)] = 1.0f;
        break;
    case TER_RANDOM:
        for (size_t i = 0; i < n; ++i)
            z[i] = (float)hash01((uint32_t)i * 2654435761U + 12345U);
        break;
    case TER_RAMP:
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                z[(size_t)j * (size_t)w + (size_t)i] = (float)(i + 0.5 * j);
        break;
    case TER_SUN_RAMP: {
        /* Every texel's horizon toward the sun is the ramp itself, at the
         * sun's elevation: the whole field is penumbra, where the ratio
         * form is most sensitive to height precision. */
        const double t = tan(15.0 * DEG), cx = cos(336.0 * DEG), cy = sin(336.0 * DEG);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                z[(size_t)j * (size_t)w + (size_t)i] = (float)(t * (i * cx + j * cy + h));
        if (c->relief > 0.0)
            z[(size_t)(h / 2) * (size_t)w + (size_t)(w / 2)] = (float)c->relief;
        return 0; /* the relief is the spike's, not a rescale */
    }
    }
    if (c->relief > 0.0) {
        float lo = z[0], hi = z[0];
        for (size_t i = 1; i < n; ++i) {
            lo = z[i] < lo ? z[i] : lo;
            hi = z[i] > hi ? z[i] : hi;
        }
        if (hi > lo)
            for (size_t i = 0; i < n; ++i)
                z[i] = (float)(((double)z[i] - lo) / ((double)hi - lo) * c->relief);
    }
    return 0;
}

/* Punches the holes of HOLES_RAW / HOLES_FILLED; returns how many. */
static long make_holes(const stress_case *c, float *z)
{
    const int w = c->w, h = c->h;
    long count = 0;
    if (c->holes == HOLES_RAW) {
        z[(size_t)(h / 2) * (size_t)w + (size_t)(w / 3)] = NAN;
        return 1;
    }
    if (c->holes == HOLES_RAW_INF) {
        z[(size_t)(h / 3) * (size_t)w + (size_t)(w / 2)] = INFINITY;
        z[(size_t)w * (size_t)h - 1] = -INFINITY;
        return 2;
    }
    if (c->holes != HOLES_FILLED)
        return 0;
    const float kinds[4] = {NAN, INFINITY, -INFINITY, NODATA};
    for (int k = 0; k < 24; ++k) {
        const int i = (int)(hash01(2U * (uint32_t)k + 1U) * w);
        const int j = (int)(hash01(2U * (uint32_t)k + 2U) * h);
        float *p = &z[(size_t)j * (size_t)w + (size_t)i];
        count += isfinite(*p) && *p != NODATA;
        *p = kinds[k % 4];
    }
    /* A block hole on the border, where push-pull has the fewest neighbours. */
    for (int j = 0; j < 6 && j < h; ++j)
        for (int i = 0; i < 6 && i < w; ++i) {
            float *p = &z[(size_t)j * (size_t)w + (size_t)i];
            count += isfinite(*p) && *p != NODATA;
            *p = NAN;
        }
    return count;
}

/* ---- lighting -------------------------------------------------------------------- */

/* The field's extent in world units. */
typedef struct extent {
    double x1, y1;       /* (W-1) dx, (H-1) dx */
    double zmin, zmax;
    double size;         /* max of x1, y1, zmax - zmin: the scene's size */
    int imax, jmax;      /* the highest grid point */
} extent;

static void field_extent(const hfs_field *f, extent *e)
{
    e->x1 = (f->width - 1) * f->dx;
    e->y1 = (f->height - 1) * f->dx;
    e->zmin = e->zmax = f->zscale * f->z[0];
    e->imax = e->jmax = 0;
    for (int j = 0; j < f->height; ++j)
        for (int i = 0; i < f->width; ++i) {
            const double z = f->zscale * f->z[(size_t)j * (size_t)f->width + (size_t)i];
            if (z > e->zmax) {
                e->zmax = z;
                e->imax = i;
                e->jmax = j;
            }
            e->zmin = z < e->zmin ? z : e->zmin;
        }
    e->size = fmax(fmax(e->x1, e->y1), e->zmax - e->zmin);
}

/* A non-negative, coloured, non-uniform sky: radiance 1 + 0.2 z + 0.15 x
 * + small band-2/3 terms (min over the sphere ~0.7 of the mean). */
static void sky(hfs_lighting *l, double scale)
{
    static const double tint[3] = {1.0, 0.9, 0.75};
    l->has_env = 1;
    for (int c = 0; c < 3; ++c) {
        double *sh = l->env_sh[c];
        memset(sh, 0, HFS_SH_COEFFS * sizeof *sh);
        sh[0] = sqrt(4.0 * PI);
        sh[1] = 0.1;
        sh[2] = 0.4;
        sh[3] = 0.3;
        sh[6] = 0.1;
        sh[8] = -0.05;
        sh[12] = 0.05;
        for (int k = 0; k < HFS_SH_COEFFS; ++k)
            sh[k] *= scale * tint[c];
    }
    l->env_rotate = 0.3;
}

static void uniform_sky(hfs_lighting *l, double radiance)
{
    l->has_env = 1;
    for (int c = 0; c < 3; ++c) {
        memset(l->env_sh[c], 0, sizeof l->env_sh[c]);
        l->env_sh[c][0] = radiance * sqrt(4.0 * PI);
    }
}

static void key(hfs_lighting *l, double phi, double elev, double alpha, double le)
{
    hfs_key_light *k = &l->key[l->n_key++];
    k->phi = phi;
    k->elev = elev;
    k->alpha = alpha;
    k->radiance[0] = (float)le;
    k->radiance[1] = (float)(le * 0.93);
    k->radiance[2] = (float)(le * 0.83);
}

static void local(hfs_lighting *l, double x, double y, double z, double r, double le)
{
    hfs_local_light *o = &l->local[l->n_local++];
    o->pos[0] = x;
    o->pos[1] = y;
    o->pos[2] = z;
    o->radius = r;
    o->radiance[0] = o->radiance[1] = o->radiance[2] = (float)le;
}

/* Sky, the test scenes' sun (azimuth 336, elevation 15, radius 2 degrees)
 * and a local light of radius size/25 above the field. */
static void std_lights(hfs_lighting *l, const extent *e, double radiance)
{
    sky(l, radiance);
    key(l, 336.0 * DEG, 15.0 * DEG, 2.0 * DEG, 300.0 * radiance);
    local(l, 0.3 * e->x1, 0.6 * e->y1, e->zmax + 0.25 * e->size, 0.04 * e->size, 20.0 * radiance);
}

/* Equirect 64x32 map, 0 but one pixel (col, row) of 1e5, projected by the
 * library (hfs_sh_project_equirect, as `--env-map` does). */
static void hot_pixel_env(hfs_lighting *l, int col, int row)
{
    enum { EW = 64, EH = 32 };
    static float rgb[EW * EH * 3];
    memset(rgb, 0, sizeof rgb);
    for (int c = 0; c < 3; ++c)
        rgb[((size_t)row * EW + (size_t)col) * 3 + (size_t)c] = 1e5f;
    double sh[3][HFS_SH_N];
    hfs_sh_project_equirect(rgb, EW, EH, sh);
    l->has_env = 1;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < HFS_SH_COEFFS; ++k)
            l->env_sh[c][k] = sh[c][k];
}

static void make_lighting(stress_light kind, const hfs_field *f, hfs_lighting *l)
{
    extent e;
    field_extent(f, &e);
    hfs_lighting_defaults(l);
    l->albedo = 0.8;
    const double zmid = 0.5 * (e.zmin + e.zmax);
    switch (kind) {
    case LIGHT_STD:
        std_lights(l, &e, 1.0);
        break;
    case LIGHT_SKY_UNIFORM:
        uniform_sky(l, 1.0);
        l->albedo = 1.0;
        break;
    case LIGHT_KEY_ZENITH:
        sky(l, 1.0);
        key(l, 0.0, PI / 2, 2.0 * DEG, 300.0);
        break;
    case LIGHT_KEY_HORIZON:
        sky(l, 1.0);
        key(l, 40.0 * DEG, 0.0, 2.0 * DEG, 300.0);
        break;
    case LIGHT_KEY_BELOW:
        sky(l, 1.0);
        key(l, 200.0 * DEG, -11.0 * DEG, 2.0 * DEG, 300.0);
        break;
    case LIGHT_KEY_NADIR:
        sky(l, 1.0);
        key(l, 0.0, -PI / 2, 2.0 * DEG, 300.0);
        break;
    case LIGHT_KEY_HUGE:
        key(l, 120.0 * DEG, 30.0 * DEG, 1.5, 1.0);
        break;
    case LIGHT_KEY_TINY:
        sky(l, 1.0);
        key(l, 70.0 * DEG, 25.0 * DEG, 1e-5, 3e9); /* E ~ pi alpha^2 Le ~ 1 */
        break;
    case LIGHT_KEY_GRAZING:
        /* In the plane of TER_SUN_RAMP: half the disk above every texel's
         * tangent plane, E = 2/3 alpha^3 (the textbook straddling formula
         * returns 0 here: its two O(alpha) terms cancel completely). */
        key(l, 336.0 * DEG, 15.0 * DEG, 1e-8, 1.0 / (PI * 1e-16));
        break;
    case LIGHT_STD_UNIFORM:
        std_lights(l, &e, 1.0);
        uniform_sky(l, 1.0);
        break;
    case LIGHT_TINY:
        /* Below float's angular resolution: windows e +- alpha collapse. */
        uniform_sky(l, 1.0);
        key(l, 200.0 * DEG, 40.0 * DEG, 1e-8, 1.0 / (PI * 1e-16));
        local(l, 0.4 * e.x1, 0.7 * e.y1, e.zmax + 2.0 * e.size, 1e-8 * 2.0 * e.size, 1.0 / (PI * 1e-16));
        break;
    case LIGHT_LOCAL_BURIED: {
        sky(l, 1.0);
        /* Inside the highest cone, well below its surface (slope 0.8: the
         * surface is 0.78 depth away from a point on the axis). */
        const double depth = 0.5 * (e.zmax - e.zmin);
        local(l, e.imax * f->dx, e.jmax * f->dx, e.zmax - depth, 0.3 * depth, 50.0);
        /* Under the whole field. */
        local(l, 0.5 * e.x1, 0.5 * e.y1, e.zmin - e.size, 0.5 * e.size, 50.0);
        /* Across the surface: centred on a grid point's surface. */
        const int i = f->width / 4, j = f->height / 4;
        local(l, i * f->dx, j * f->dx, f->zscale * f->z[(size_t)j * (size_t)f->width + (size_t)i],
              3.0 * f->dx, 5.0);
        break;
    }
    case LIGHT_LOCAL_R0:
        sky(l, 1.0);
        local(l, 0.3 * e.x1, 0.6 * e.y1, e.zmax + 0.25 * e.size, 0.0, 1e3);
        break;
    case LIGHT_LOCAL_HUGE_IN:
        local(l, 0.5 * e.x1, 0.5 * e.y1, zmid, 100.0 * e.size, 2.5);
        break;
    case LIGHT_LOCAL_HUGE_OUT:
        local(l, 0.5 * e.x1, 0.5 * e.y1, e.zmax + 3.0 * e.size, 2.0 * e.size, 2.5);
        break;
    case LIGHT_LOCAL_ZENITH: {
        sky(l, 1.0);
        const int i = f->width / 2, j = f->height / 2;
        local(l, i * f->dx, j * f->dx, e.zmax + 0.1 * e.size, 0.02 * e.size, 200.0);
        const int i2 = f->width / 4, j2 = (3 * f->height) / 4;
        local(l, i2 * f->dx, j2 * f->dx, f->zscale * f->z[(size_t)j2 * (size_t)f->width + (size_t)i2],
              2.0 * f->dx, 5.0);
        break;
    }
    case LIGHT_LOCAL_HORIZON:
        sky(l, 1.0);
        local(l, -10.0 * e.size, 0.5 * e.y1, zmid, 0.5 * e.size, 400.0);
        break;
    case LIGHT_LOCAL_BELOW:
        sky(l, 1.0);
        local(l, e.x1 + e.size, 0.5 * e.y1, e.zmin - e.size, 0.5 * e.size, 20.0);
        break;
    case LIGHT_RADIANCE_0:
        std_lights(l, &e, 0.0);
        break;
    case LIGHT_RADIANCE_1E6:
        std_lights(l, &e, 1.0);
        uniform_sky(l, 1e6);
        l->key[0].radiance[0] = l->key[0].radiance[1] = l->key[0].radiance[2] = 1e6f;
        l->local[0].radiance[0] = l->local[0].radiance[1] = l->local[0].radiance[2] = 1e6f;
        break;
    case LIGHT_MIXED_1E6:
        uniform_sky(l, 1.0);
        key(l, 100.0 * DEG, 20.0 * DEG, 2.0 * DEG, 1e6);
        break;
    case LIGHT_ENV_HOT_ZENITH:
        hot_pixel_env(l, 10, 0);
        break;
    case LIGHT_ENV_HOT_HORIZON:
        hot_pixel_env(l, 20, 15);
        break;
    case LIGHT_ENV_HOT_BELOW:
        hot_pixel_env(l, 40, 24);
        break;
    }
}

/* ---- scenes ---------------------------------------------------------------------- */

int stress_scene_build(const stress_case *c, double s, stress_scene *sc, char *msg, size_t n)
{
    memset(sc, 0, sizeof *sc);
    /* A 1-wide field is generated 2 wide and then narrowed: the generators
     * and the light placement want 2x2, the renderer must see the case. */
    stress_case gen = *c;
    gen.w = c->w < 2 ? 2 : c->w;
    gen.h = c->h < 2 ? 2 : c->h;
    float *full = malloc((size_t)gen.w * (size_t)gen.h * sizeof *full);
    sc->z = malloc((size_t)c->w * (size_t)c->h * sizeof *sc->z);
    if (!full || !sc->z || make_terrain(&gen, full)) {
        free(full);
        stress_scene_free(sc);
        snprintf(msg, n, "terrain: out of memory for %dx%d heights", c->w, c->h);
        return -1;
    }
    /* Lights are placed on the unscaled, hole-free field, then scaled. */
    const hfs_field geo = {.width = gen.w, .height = gen.h, .z = full, .dx = c->dx,
                           .zscale = c->zscale};
    make_lighting(c->light, &geo, &sc->l);
    for (int j = 0; j < c->h; ++j)
        for (int i = 0; i < c->w; ++i)
            sc->z[(size_t)j * (size_t)c->w + (size_t)i] = full[(size_t)j * (size_t)gen.w + (size_t)i];
    free(full);
    sc->f.width = c->w;
    sc->f.height = c->h;
    sc->f.z = sc->z;
    sc->f.dx = c->dx;
    sc->f.zscale = c->zscale;

    const long punched = make_holes(c, sc->z);
    if (c->holes == HOLES_FILLED) {
        long filled = 0;
        hfs_error err;
        if (hfs_height_fill_holes(sc->z, c->w, c->h, 1, NODATA, &filled, &err)) {
            snprintf(msg, n, "hole fill: %s", err.msg);
            stress_scene_free(sc);
            return -1;
        }
        if (filled != punched) {
            snprintf(msg, n, "hole fill: %ld holes reported, %ld punched", filled, punched);
            stress_scene_free(sc);
            return -1;
        }
    }

    sc->f.dx *= s;
    sc->f.zscale *= s;
    for (int i = 0; i < sc->l.n_local; ++i) {
        for (int k = 0; k < 3; ++k)
            sc->l.local[i].pos[k] *= s;
        sc->l.local[i].radius *= s;
    }
    for (int ch = 0; ch < 3; ++ch) {
        double absmax;
        sc->lneg[ch] = 0.0;
        if (sc->l.has_env)
            stress_sh_range(sc->l.env_sh[ch], &sc->lneg[ch], &absmax);
    }
    hfs_quality_defaults(&sc->q);
    if (c->tables)
        sc->q.visibility = HFS_VIS_WEDGE_TABLE;
    return 0;
}

void stress_scene_free(stress_scene *sc)
{
    free(sc->z);
    memset(sc, 0, sizeof *sc);
}
