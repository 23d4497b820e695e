/*
 * test_gis_sweep_blocks.c — the windowed sweep's block bounds
 * (tools/gis/gis_sweep_blocks.h), no GDAL, no GL:
 *   cover   for every frame (either axis major, each walked up or down
 *           it, rows climbed 0 to 1 a column) and every line of it, on
 *           non-square fields of random relief (zscale negative too,
 *           sizes not a multiple of the block): the blocks' extent is
 *           never below the one taken texel by texel from the line's
 *           bands, as gis_sweep.c's band_column takes them (the blocks
 *           may only clear a line its own bands would);
 *   exact   on a field of one height the extent is that height and no
 *           rise; a lone spike is seen by the lines whose bands hold it;
 *   zabs    the largest |height| is the field's.
 */
#include "check.h"
#include "gis_sweep_blocks.h"

#include <math.h>
#include <stdlib.h>

/* The field's (x, y) of frame (u, v). */
static size_t texel_at(const hfs_field *f, const gis_sweep_frame *fr, int u, int v)
{
    const int a = fr->u_up ? u : fr->nu - 1 - u, b = fr->v_up ? v : fr->nv - 1 - v;
    const int x = fr->x_major ? a : b, y = fr->x_major ? b : a;
    return (size_t)y * (size_t)f->width + (size_t)x;
}

/* Line k's extent texel by texel: band_column's rows about the line at
 * each column (floor(y) - 2 .. floor(y) + 3 in the field), its heights,
 * its rises to the next column and between its rows. */
static gis_sweep_extent bands_of(const hfs_field *f, const gis_sweep_frame *fr, long k)
{
    gis_sweep_extent e = {HUGE_VAL, -HUGE_VAL, 0.0, 0.0, 0.0};
    const double zs = f->zscale;
    for (int u = 0; u < fr->nu; ++u) {
        const double y = (double)k + fr->r * u;
        if (y < -1.5 || y > fr->nv + 0.5)
            continue;
        const int fy = (int)floor(y);
        const int j0 = fy - 2 > 0 ? fy - 2 : 0, j1 = fy + 3 < fr->nv - 1 ? fy + 3 : fr->nv - 1;
        for (int j = j0; j <= j1; ++j) {
            const double z = zs * f->z[texel_at(f, fr, u, j)];
            e.zmin = fmin(e.zmin, z), e.zmax = fmax(e.zmax, z);
            if (u + 1 < fr->nu)
                e.du = fmax(e.du, zs * f->z[texel_at(f, fr, u + 1, j)] - z);
            if (j > j0) {
                const double prev = zs * f->z[texel_at(f, fr, u, j - 1)];
                e.dv = fmax(e.dv, z - prev);
                e.dv_abs = fmax(e.dv_abs, fabs(z - prev));
            }
        }
    }
    return e;
}

/* Every line of every frame of f: the blocks' extent at least the bands'.
 * Returns the lines checked. */
static long check_cover(const hfs_field *f, const char *what)
{
    gis_sweep_blocks b;
    CHECK(gis_sweep_blocks_make(&b, f, 2) == HFS_OK, "%s: blocks made", what);
    static const double rs[4] = {0.0, 0.3, 0.77, 1.0};
    long lines = 0, below = 0;
    for (int m = 0; m < 8; ++m)
        for (int q = 0; q < 4; ++q) {
            const int xm = m & 1;
            const gis_sweep_frame fr = {xm, (m >> 1) & 1, (m >> 2) & 1, xm ? f->width : f->height,
                                        xm ? f->height : f->width, rs[q]};
            for (long k = (long)floor(-fr.r * (fr.nu - 1)) - 1; k <= fr.nv; ++k, ++lines) {
                const gis_sweep_extent t = bands_of(f, &fr, k);
                const gis_sweep_extent e = gis_sweep_blocks_line(&b, &fr, k);
                const int ok = e.zmin <= t.zmin && e.zmax >= t.zmax && e.du >= t.du &&
                               e.dv >= t.dv && e.dv_abs >= t.dv_abs;
                below += !ok;
                if (!ok && below <= 3)
                    CHECK(0, "%s: frame %d r %.2f line %ld: blocks %g..%g du %g dv %g |dv| %g "
                          "below the bands' %g..%g du %g dv %g |dv| %g", what, m, fr.r, k,
                          e.zmin, e.zmax, e.du, e.dv, e.dv_abs, t.zmin, t.zmax, t.du, t.dv,
                          t.dv_abs);
            }
        }
    CHECK(below == 0, "%s: %ld of %ld lines' blocks below their bands", what, below, lines);
    gis_sweep_blocks_free(&b);
    return lines;
}

static float *random_field(int w, int h, unsigned seed)
{
    float *z = malloc((size_t)w * (size_t)h * sizeof *z);
    srand(seed);
    for (size_t p = 0; p < (size_t)w * (size_t)h; ++p)
        z[p] = (float)(50.0 * rand() / (double)RAND_MAX);
    return z;
}

static void test_cover(void)
{
    static const int sizes[4][2] = {{37, 21}, {19, 44}, {8, 8}, {3, 30}};
    long lines = 0;
    for (int s = 0; s < 4; ++s) {
        const int w = sizes[s][0], h = sizes[s][1];
        float *z = random_field(w, h, 5u + (unsigned)s);
        const hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.7, .zscale = 1.3};
        const hfs_field g = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = -0.8};
        lines += check_cover(&f, "zscale 1.3") + check_cover(&g, "zscale -0.8");
        free(z);
    }
    printf("cover: %ld lines, the blocks' extent never below the bands'\n", lines);
}

static void test_exact_and_zabs(void)
{
    const int w = 29, h = 17;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (size_t p = 0; p < (size_t)w * h; ++p)
        z[p] = 4.0f;
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 2.0};
    gis_sweep_blocks b;
    CHECK(gis_sweep_blocks_make(&b, &f, 1) == HFS_OK, "flat: made");
    const gis_sweep_frame fr = {1, 1, 0, w, h, 0.4};
    const gis_sweep_extent e = gis_sweep_blocks_line(&b, &fr, 5);
    CHECK(e.zmin == 8.0 && e.zmax == 8.0 && e.du == 0.0 && e.dv == 0.0 && e.dv_abs == 0.0,
          "flat: %g..%g du %g dv %g", e.zmin, e.zmax, e.du, e.dv);
    gis_sweep_blocks_free(&b);
    /* a spike at (20, 3) of height -50 scaled by -2: the highest point, a
     * rise of 100 into it from each side, and |zabs| 100 */
    z[3 * w + 20] = -46.0f;
    const hfs_field g = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = -2.0};
    CHECK(gis_sweep_blocks_make(&b, &g, 3) == HFS_OK, "spike: made");
    CHECK(gis_sweep_blocks_zabs(&b) == 92.0, "spike: zabs %g", gis_sweep_blocks_zabs(&b));
    /* along +x, rows climbing 0: line k = 3 holds the spike, k = 12 not */
    const gis_sweep_frame ax = {1, 1, 1, w, h, 0.0};
    const gis_sweep_extent on = gis_sweep_blocks_line(&b, &ax, 3);
    const gis_sweep_extent off = gis_sweep_blocks_line(&b, &ax, 12);
    CHECK(on.zmax == 92.0 && on.du == 100.0 && on.dv == 100.0, "spike seen: max %g du %g dv %g",
          on.zmax, on.du, on.dv);
    CHECK(off.zmax == -8.0 && off.du == 0.0, "spike not seen 9 rows away: max %g du %g",
          off.zmax, off.du);
    gis_sweep_blocks_free(&b);
    free(z);
}

int main(void)
{
    test_cover();
    test_exact_and_zabs();
    printf("test_gis_sweep_blocks: %ld checks, %d failures\n", checks, failures);
    return failures != 0;
}
