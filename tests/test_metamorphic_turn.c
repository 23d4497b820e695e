/*
 * test_metamorphic_turn.c — turning or mirroring the world turns or
 * mirrors the picture (issue 35, deliverable 1).  A non-square field (41 x
 * 25, dx 0.7) turned by 90, 180 or 270 degrees (heights rotated, width and
 * height swapped), mirrored (rows or columns flipped), or transposed, with
 * every key light's azimuth, the SH sky (hfs_sh_mirror_y, hfs_sh_rotate_z),
 * the local light and the queried points moved the same way, must give the
 * image moved that way and the same points' visibility.  Bugs that mix up
 * a field's width and height (rows placed by its width, an aspect used the
 * wrong way round) are right on a square field and break this.
 *
 * Why 41 x 25: the renderer's grids (the 2x2 visibility grid, the split
 * horizons' far grid of step 2 or 8, the bounces' grid of step 4) hold
 * texels 0, s, 2 s, ... and the last one; with W - 1 and H - 1 multiples
 * of 8 every grid is its own mirror image, so the relation can hold
 * exactly.  The environment's 12 directions start at azimuth 0 (a
 * multiple of 4: every quarter turn and mirror maps the set onto itself),
 * and each key light's swath is centred on its azimuth.
 *
 *   test_metamorphic_turn cpu | gles SUBSAMPLE   (gles: 77 without a context)
 */
#include "metamorphic.h"
#include "sh.h"

#include <stdlib.h>

#define W 41
#define H 25
#define PI 3.14159265358979323846

/* A symmetry of the grid: rows flipped first when `mirror` (y -> -y),
 * then turned by `quarter` x 90 degrees (from +x toward +y). */
typedef struct turn {
    int quarter, mirror;
    const char *name;
} turn;

static const turn turns[] = {
    {1, 0, "turned 90"}, {2, 0, "turned 180"}, {3, 0, "turned 270"},
    {0, 1, "mirrored (rows)"}, {2, 1, "mirrored (columns)"}, {1, 1, "transposed"},
    {3, 1, "anti-transposed"},
};

/* Grid position (gx, gy) of a w x h field moved by t, into (ox, oy) of
 * the moved field: about the field's centre, which stays its centre. */
static void move_grid(const turn *t, int w, int h, double gx, double gy, double *ox, double *oy)
{
    double u = gx - 0.5 * (w - 1), v = gy - 0.5 * (h - 1);
    if (t->mirror)
        v = -v;
    for (int q = 0; q < t->quarter; ++q) {
        const double k = u;
        u = -v, v = k;
    }
    const int odd = t->quarter % 2;
    *ox = u + 0.5 * ((odd ? h : w) - 1);
    *oy = v + 0.5 * ((odd ? w : h) - 1);
}

static double move_phi(const turn *t, double phi)
{
    return (t->mirror ? -phi : phi) + t->quarter * 0.5 * PI;
}

/* World position p (x, y) moved by t (z stays). */
static void move_world(const turn *t, const hfs_field *f, const double p[3], double out[3])
{
    move_grid(t, f->width, f->height, p[0] / f->dx, p[1] / f->dx, &out[0], &out[1]);
    out[0] *= f->dx, out[1] *= f->dx, out[2] = p[2];
}

/* The scene sc moved by t into out. */
static void move_scene(const turn *t, const mm_scene *sc, mm_scene *out)
{
    const int w = sc->f.width, h = sc->f.height;
    *out = *sc;
    out->f.z = out->z;
    out->f.width = t->quarter % 2 ? h : w;
    out->f.height = t->quarter % 2 ? w : h;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double x, y;
            move_grid(t, w, h, i, j, &x, &y);
            out->z[(int)lround(y) * out->f.width + (int)lround(x)] = sc->z[j * w + i];
        }
    for (int c = 0; c < 3; ++c) {
        double s[HFS_SH_N];
        memcpy(s, sc->l.env_sh[c], sizeof s);
        if (t->mirror)
            hfs_sh_mirror_y(s, s);
        hfs_sh_rotate_z(s, t->quarter * 0.5 * PI, out->l.env_sh[c]);
    }
    for (int k = 0; k < sc->l.n_key; ++k)
        out->l.key[k].phi = move_phi(t, sc->l.key[k].phi);
    for (int k = 0; k < sc->l.n_local; ++k)
        move_world(t, &sc->f, sc->l.local[k].pos, out->l.local[k].pos);
    for (int p = 0; p < MM_NPTS; ++p)
        move_world(t, &sc->f, sc->xyz + 3 * p, out->xyz + 3 * p);
}

/* The largest difference between a and the moved b read back at a's
 * texels, over a's maximum. */
static double compare_moved(const turn *t, const hfs_image *a, const hfs_image *b)
{
    const int w = a->width, h = a->height;
    double d = 0.0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double x, y;
            move_grid(t, w, h, i, j, &x, &y);
            const float *pa = a->rgb + 3 * (j * w + i);
            const float *pb = b->rgb + 3 * ((int)lround(y) * b->width + (int)lround(x));
            for (int c = 0; c < 3; ++c)
                d = fmax(d, fabs((double)pa[c] - pb[c]));
        }
    const double peak = mm_peak(a);
    return peak > 0.0 ? d / peak : d;
}

/* GLES, per subsample (1, 2): the product (fp16, split horizons), one
 * bounce, and fp32.  Measured on Mesa 22.3.6 llvmpipe, the largest over
 * the seven moves; bounds 1.2x that.
 *   - fp32 without the split (subsample 1) and with it (subsample 2):
 *     1.9e-6 and 1.4e-6, float rounding (directions as cos/sin of turned
 *     angles): the algorithm keeps the relation.
 *   - fp16 at subsample 2 with the split, 4.6e-4 at one texel, where
 *     fp16's rounding of a stored occluder flips a decision (fp32 there:
 *     1.4e-6).
 *   - one bounce: before issue 36 bounce frames turned split horizons
 *     off, 1.4e-5 (subsample 1) and 5.3e-6 (subsample 2), fp16 rounding
 *     of the same values; since then they keep them, and the direct part
 *     brings the split's own moves: 5.9e-3 (subsample 1, the atlas fetch
 *     below; 1.6e-3 since) and 3.6e-4 (subsample 2, the stored occluder
 *     above).
 *   - the product at subsample 1: 6.8e-3 at a few isolated texels, fp32
 *     the same (so not fp16), until session 36.  The far grid (step 2) is
 *     read with one LINEAR fetch of its atlas (env_slices.frag); a texel
 *     on a receiver should get that receiver's pair alone, but its
 *     coordinate (the grid coordinate divided by the tile size and
 *     multiplied back, then by the atlas size in the sampler) landed a
 *     rounding error off the texel centre, and the sampler's quantized
 *     weights then gave the neighbour a small weight.  Where the
 *     neighbour has no occluder (HFS_SPLIT_NONE_H, -3e4) that lost this
 *     texel's occluder, at texels that followed the coordinates'
 *     rounding, which no turn keeps.  Texels beside a wall's top read the
 *     grid on a receiver or an edge (hfs_grid_snap), which made it
 *     larger (over the bound: one bounce, turned 180); since the
 *     coordinate is taken in the tile's texels (hfs_grid_pix_at), 2.1e-3
 *     and 1.6e-3 (one bounce).
 *     The four receivers read with texelFetch and blended exactly gave
 *     1.4e-5 by hand (the fp16 level; the CPU blends exactly: 0).
 * Points: the shadow height maps in float, 1.2e-6 (10 ulps of 1). */
static const mm_setting gles_settings[2][3] = {
    {{HFS_PRECISION_FP16, 1, 0, 1, 2.5e-3, 1.5e-6},
     {HFS_PRECISION_FP16, 1, 1, 1, 1.9e-3, 1.5e-6},
     {HFS_PRECISION_FP32, 0, 0, 1, 2.3e-6, 1.5e-6}},
    {{HFS_PRECISION_FP16, 1, 0, 1, 5.5e-4, 1.5e-6},
     {HFS_PRECISION_FP16, 1, 1, 1, 4.4e-4, 1.5e-6},
     {HFS_PRECISION_FP32, 1, 0, 1, 1.7e-6, 1.5e-6}},
};

static void turn_invariance(hfs_renderer *r, const char *name, int sub, const mm_setting *st)
{
    const hfs_quality q = mm_quality(sub, st);
    static mm_scene base, moved;
    mm_scene_make(&base, W, H, 1.0);
    base.l.bounces = st->bounces;
    mm_result rb, rm;
    REQUIRE(mm_render(r, &base, &q, &rb) == 0, "%s: the base scene", name);
    for (size_t i = 0; i < sizeof turns / sizeof turns[0]; ++i) {
        const turn *t = &turns[i];
        move_scene(t, &base, &moved);
        REQUIRE(mm_render(r, &moved, &q, &rm) == 0, "%s: the scene %s", name, t->name);
        const double d_img = compare_moved(t, &rb.img, &rm.img);
        hfs_image_free(&rm.img);
        mm_report(name, sub, st, t->name, d_img, mm_vis_diff(&rb, &rm, MM_NPTS * base.l.n_key));
    }
    hfs_image_free(&rb.img);
}

static void run(hfs_renderer *r, const char *backend, int sub)
{
    if (!strcmp(backend, "gles")) {
        for (int i = 0; i < 3; ++i)
            turn_invariance(r, "gles", sub, &gles_settings[sub == 1 ? 0 : 1][i]);
        return;
    }
    /* Double precision, the same arithmetic mirrored: measured 0, also
     * with a bounce. */
    const mm_setting exact[2] = {{HFS_PRECISION_FP32, 1, 0, 1, 1e-6, 1e-6},
                                 {HFS_PRECISION_FP32, 1, 1, 1, 1e-6, 1e-6}};
    for (sub = 1; sub <= 2; ++sub)
        for (int i = 0; i < 2; ++i)
            turn_invariance(r, "cpu", sub, &exact[i]);
}

int main(int argc, char **argv)
{
    return mm_main(argc, argv, "test_metamorphic_turn", run);
}
