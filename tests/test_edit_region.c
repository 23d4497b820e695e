/*
 * test_edit_region.c — the regions of runtime/gles/edit_region.h against
 * brute force, without a driver (issue 38): the changed box, its top, the
 * tile masks and their scissor rectangles (cover exactly the marked
 * tiles, never overlap), growth by a reach (every texel within the reach
 * of a marked one is marked), the key light's sweep (every texel whose ray
 * meets the box within t_max is in it), the layers' reaches.
 */
#include "check.h"
#include "edit_region.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng = 0x2545f4914f6cdd1dull;

static int pick(int n)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (int)((rng >> 11) % (uint64_t)n);
}

static double uni(void)
{
    return pick(1 << 30) / (double)(1 << 30);
}

static void test_find(void)
{
    for (int trial = 0; trial < 200; ++trial) {
        const int w = 1 + pick(70), h = 1 + pick(50);
        float *a = malloc(sizeof(float) * w * h), *b = malloc(sizeof(float) * w * h);
        for (int i = 0; i < w * h; ++i)
            a[i] = b[i] = (float)pick(100);
        const int changes = pick(4);
        int x0 = w, y0 = h, x1 = -1, y1 = -1;
        for (int c = 0; c < changes; ++c) {
            const int x = pick(w), y = pick(h);
            /* -0 against 0 is a change of bits */
            b[y * w + x] = a[y * w + x] == 0.0f && pick(2) ? -0.0f : a[y * w + x] + 1.0f;
            x0 = x < x0 ? x : x0, y0 = y < y0 ? y : y0;
            x1 = x > x1 ? x : x1, y1 = y > y1 ? y : y1;
        }
        hfs_edit_box box;
        const int found = hfs_edit_find(a, b, w, h, &box);
        CHECK(found == (changes > 0), "trial %d: found %d with %d changes", trial, found, changes);
        if (found && changes > 0)
            CHECK(box.x0 == x0 && box.y0 == y0 && box.x1 == x1 && box.y1 == y1,
                  "trial %d: box (%d %d %d %d) want (%d %d %d %d)", trial, box.x0, box.y0,
                  box.x1, box.y1, x0, y0, x1, y1);
        free(a);
        free(b);
    }
}

static int marked(const hfs_tiles *t, int x, int y)
{
    return t->all || t->on[(size_t)(y / HFS_EDIT_TILE) * t->tw + x / HFS_EDIT_TILE];
}

static void test_tiles(void)
{
    hfs_tiles t = {0}, g = {0};
    for (int trial = 0; trial < 100; ++trial) {
        const int w = 1 + pick(150), h = 1 + pick(120), r = pick(40);
        if (hfs_tiles_init(&t, w, h) || hfs_tiles_init(&g, w, h)) {
            CHECK(0, "out of memory");
            return;
        }
        for (int k = pick(4); k > 0; --k) {
            const int x = pick(w) - 5, y = pick(h) - 5;
            hfs_tiles_add_box(&t, (hfs_edit_box){x, y, x + pick(30), y + pick(30)});
        }
        /* the rectangles: exactly the marked tiles' texels, once each */
        hfs_edit_rect *rc = malloc(sizeof *rc * (size_t)(t.tw * t.th + 1));
        unsigned char *cover = calloc((size_t)w * h, 1);
        const int n = hfs_tiles_rects(&t, rc);
        for (int i = 0; i < n; ++i)
            for (int y = rc[i].y; y < rc[i].y + rc[i].h; ++y)
                for (int x = rc[i].x; x < rc[i].x + rc[i].w; ++x) {
                    CHECK(x >= 0 && y >= 0 && x < w && y < h, "rectangle outside the field");
                    if (x >= 0 && y >= 0 && x < w && y < h)
                        ++cover[y * w + x];
                }
        int bad = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                bad += cover[y * w + x] != marked(&t, x, y);
        CHECK(bad == 0, "trial %d: %d texels covered wrongly by %d rectangles", trial, bad, n);
        /* grown: every texel within r (each axis) of a marked one */
        hfs_tiles_add_grown(&g, &t, r);
        bad = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                if (!marked(&t, x, y))
                    continue;
                for (int dy = -r; dy <= r; dy += r > 0 ? r : 1)
                    for (int dx = -r; dx <= r; dx += r > 0 ? r : 1) {
                        const int qx = x + dx, qy = y + dy;
                        if (qx >= 0 && qy >= 0 && qx < w && qy < h && !marked(&g, qx, qy))
                            ++bad;
                    }
            }
        CHECK(bad == 0, "trial %d: %d texels within %d of a marked one unmarked", trial, bad, r);
        free(rc);
        free(cover);
    }
    hfs_tiles_set_all(&t);
    hfs_edit_rect one[2];
    CHECK(hfs_tiles_rects(&t, one) == 1 && one[0].w == t.w && one[0].h == t.h,
          "all: one rectangle, the field");
    CHECK(hfs_tiles_any(&t), "all: any");
    hfs_tiles_clear(&t);
    CHECK(!hfs_tiles_any(&t), "cleared: none");
    hfs_tiles_free(&t);
    hfs_tiles_free(&g);
}

static void test_sweep(void)
{
    for (int trial = 0; trial < 300; ++trial) {
        const int w = 20 + pick(200), h = 20 + pick(200);
        const int x0 = pick(w), y0 = pick(h);
        const hfs_edit_box e = {x0, y0, x0 + pick(10), y0 + pick(10)};
        const double phi = uni() * 6.283185307179586, c = cos(phi), s = sin(phi);
        const double t_max = pick(3) ? uni() * 300.0 : 0.0;
        const hfs_edit_box b = hfs_edit_sweep(e, c, s, t_max, w, h);
        int bad = 0;
        for (int k = 0; k < 400; ++k) {
            const int px = pick(w), py = pick(h);
            int hits = px >= e.x0 && px <= e.x1 && py >= e.y0 && py <= e.y1;
            for (double t = 0.0; t <= t_max && !hits; t += 0.25) {
                const double qx = px + c * t, qy = py + s * t;
                hits = qx >= e.x0 && qx <= e.x1 && qy >= e.y0 && qy <= e.y1;
            }
            bad += hits && !(px >= b.x0 && px <= b.x1 && py >= b.y0 && py <= b.y1);
        }
        CHECK(bad == 0, "trial %d: %d texels whose ray meets the box outside the sweep", trial,
              bad);
    }
    CHECK(hfs_edit_reach_above(1.0, -1.0, 2.0, 0.5) == 8.0, "reach above: (1+1) 2 / 0.5");
    CHECK(isinf(hfs_edit_reach_above(1.0, -1.0, 2.0, 0.0)) &&
              isinf(hfs_edit_reach_above(1.0, -1.0, 2.0, -0.1)),
          "reach above: no bound for a slope not above 0");
}

static void test_reach(void)
{
    const int sizes[3] = {64, 512, 1500};
    for (int i = 0; i < 3; ++i) {
        const int n = sizes[i];
        float *z = calloc((size_t)n * n, sizeof *z);
        z[0] = 1.0f;
        const hfs_field f = {.width = n, .height = n, .z = z, .dx = 1.0, .zscale = 1.0};
        hfs_quality q;
        hfs_quality_defaults(&q);
        q.offset = 2; /* filtered levels read */
        hfs_gles_layout L;
        hfs_error err;
        if (hfs_gles_layout_init(&L, &f, &q, &err)) {
            CHECK(0, "layout: %s", err.msg);
            free(z);
            continue;
        }
        CHECK(hfs_edit_layer_reach(&L, L.n_layers - 1) == 1.0, "the input's reach is its cell");
        for (int l = 0; l + 1 < L.n_layers; ++l) {
            const int lev = l + L.lmin;
            const double r = hfs_edit_layer_reach(&L, l);
            CHECK(r > hfs_edit_layer_reach(&L, l + 1), "size %d layer %d: coarser reaches further",
                  n, l);
            CHECK(r >= 3.0 * L.spacing[lev], "size %d layer %d: at least the B-spline's 2 "
                  "spacings and the read", n, l);
        }
        CHECK(hfs_edit_env_near_reach(&L, L.n_levels - 1) >= 3.0, "near reach: the cell");
        CHECK(hfs_edit_env_near_reach(&L, 0) >= L.spacing[0] * pow(2.0, 1.0 / L.k),
              "near reach: the coarsest scale, refined");
        free(z);
    }
}

int main(void)
{
    test_find();
    test_tiles();
    test_sweep();
    test_reach();
    if (failures)
        printf("%d failures\n", failures);
    else
        printf("edit regions: all checks passed\n");
    return failures ? 1 : 0;
}
