/*
 * test_kiosk_map.c — the kiosk's map (board/kiosk_map.h; issue 40 item 4),
 * on the CPU reference (deterministic, any size):
 *   - the levels a field needs on a display, and the view's size;
 *   - the whole-field level: one tile whose window is the whole level, so
 *     its frame equals a render of that level's field (2x2 means of 2x2
 *     means, computed here independently) bit for bit, its albedo map too;
 *   - level 0 (a texel a pixel), tiles lit through halos: against the crop
 *     of one render of the whole field, within the bounds below (terrain
 *     beyond a halo stays under hfs_tile_eps, 1.27 deg for the sky), in the
 *     middle and at the far corner (a view past it kept on the field);
 *   - a tile's halo from its own relief never wider than the level's, and
 *     a local light (no halo is enough): the whole level, exact;
 *   - ahead of the pan: after kiosk_map_prefetch has fetched every tile
 *     the view wants, a pan of up to a tile and a zoom step in render
 *     nothing themselves, the cache within its budget, and every frame
 *     equal, bit for bit, to a new map's frame of the same view;
 *   - a jump past the tiles ahead: shown at once from the coarser level,
 *     then the view's own tiles lit first, and the view equal to a new
 *     map's;
 *   - a new lighting drops the tiles: the next frame renders its own and
 *     equals a new map's.
 */
#include "check.h"
#include "kiosk_map_priv.h" /* kiosk_map_tile_halo */
#include "terrain_gen.h"
#include "tiled_render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define W 1024
#define H 512
#define DW 160
#define DH 120
/* Level 0 against the whole field's render, of its maximum, about 1.2x
 * what was measured (printed below): in the middle mean 2.16e-7, max
 * 3.1e-6; at the far corner 8.06e-7, 7.62e-6. */
static const double bound_mid[2] = {2.6e-7, 3.7e-6}, bound_corner[2] = {9.7e-7, 9.2e-6};

static hfs_renderer *cpu(void)
{
    const hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    if (hfs_renderer_create(&d, &r, &err)) {
        fprintf(stderr, "FAIL: renderer: %s\n", err.msg);
        exit(1);
    }
    return r;
}

static void render(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                   const hfs_quality *q, hfs_image *out)
{
    hfs_error err = {""};
    hfs_renderer_set_field_serial(r, 0);
    if (hfs_image_alloc(out, f->width, f->height, &err) ||
        hfs_renderer_render(r, f, l, q, out, NULL, NULL, &err)) {
        fprintf(stderr, "FAIL: render: %s\n", err.msg);
        exit(1);
    }
}

/* 2x2 means, ch channels (the far edge's blocks of what they have). */
static float *halve(const float *s, int w, int h, int ch)
{
    const int hw = (w + 1) / 2, hh = (h + 1) / 2;
    float *d = malloc((size_t)hw * hh * ch * sizeof *d);
    for (int j = 0; j < hh; ++j)
        for (int i = 0; i < hw; ++i)
            for (int c = 0; c < ch; ++c) {
                double sum = 0.0;
                for (int b = 0; b < 4; ++b) {
                    const int x = 2 * i + (b & 1) < w ? 2 * i + (b & 1) : 2 * i;
                    const int y = 2 * j + (b >> 1) < h ? 2 * j + (b >> 1) : 2 * j;
                    sum += s[((size_t)y * w + x) * ch + c];
                }
                d[((size_t)j * hw + i) * ch + c] = (float)(sum / 4.0);
            }
    return d;
}

typedef struct world {
    float *z, *albedo;
    hfs_scene_inputs in;
    hfs_quality q;
} world;

static void make_world(world *w)
{
    memset(w, 0, sizeof *w);
    w->z = malloc(sizeof(float) * W * H);
    hfs_terrain_fractal(w->z, W, H, 7u, 1.0);
    float lo = INFINITY, hi = -INFINITY;
    for (int p = 0; p < W * H; ++p)
        lo = fminf(lo, w->z[p]), hi = fmaxf(hi, w->z[p]);
    for (int p = 0; p < W * H; ++p) /* 20 m of relief on 30 m cells: halos of 48 */
        w->z[p] = 20.0f * (w->z[p] - lo) / (hi - lo);
    w->in.field = (hfs_field){W, H, w->z, 30.0, 1.0};
    hfs_lighting_defaults(&w->in.lighting);
    hfs_lighting *l = &w->in.lighting;
    l->has_env = 1;
    for (int c = 0; c < 3; ++c)
        l->env_sh[c][0] = 3.5449077;
    l->n_key = 1;
    l->key[0] = (hfs_key_light){.phi = 2.0, .elev = 12.0 * PI / 180.0,
                                .alpha = 1.0 * PI / 180.0, .radiance = {20, 18, 15}};
    hfs_quality_defaults(&w->in.quality);
    hfs_quality_preset(&w->in.quality, "headless");
    /* few directions: the map's tiles are rendered as the whole field is,
     * whatever the quality, and this test renders many (ASan builds too) */
    w->in.quality.nphi_env = 4;
    w->in.quality.nphi_key = 1;
    w->in.quality.nphi_bounce = 4;
    w->in.serial = 1;
}

static kiosk_map *new_map(const world *w)
{
    kiosk_map *m = NULL;
    hfs_error err = {""};
    if (kiosk_map_create(&w->in, DW, DH, &m, &err)) {
        fprintf(stderr, "FAIL: map: %s\n", err.msg);
        exit(1);
    }
    return m;
}

/* m's view of level l at (cx, cy) into out (allocated); its stats. */
static kiosk_map_stats frame(kiosk_map *m, hfs_renderer *r, const world *w, double cx,
                             double cy, int l, hfs_image *out)
{
    int vw, vh;
    kiosk_map_view_size(m, l, &vw, &vh);
    hfs_error err = {""};
    hfs_image_free(out);
    if (hfs_image_alloc(out, vw, vh, &err) ||
        kiosk_map_frame(m, r, &w->in, cx, cy, l, out, &err)) {
        fprintf(stderr, "FAIL: map frame: %s\n", err.msg);
        exit(1);
    }
    kiosk_map_stats s;
    kiosk_map_stats_get(m, &s);
    return s;
}

static int same(const hfs_image *a, const hfs_image *b)
{
    return a->width == b->width && a->height == b->height &&
           !memcmp(a->rgb, b->rgb, sizeof(float) * 3 * (size_t)a->width * a->height);
}

/* A frame of a new map equals out (the same view, nothing cached). */
static int as_new(const world *w, hfs_renderer *r, double cx, double cy, int l,
                  const hfs_image *out)
{
    kiosk_map *m = new_map(w);
    hfs_image img = {0};
    frame(m, r, w, cx, cy, l, &img);
    const int ok = same(&img, out);
    hfs_image_free(&img);
    kiosk_map_free(m);
    return ok;
}

static void levels(void)
{
    CHECK(kiosk_map_levels_for(W, H, DW, DH) == 4, "%dx%d on %dx%d: %d levels", W, H, DW, DH,
          kiosk_map_levels_for(W, H, DW, DH));
    CHECK(kiosk_map_levels_for(DW, DH, DW, DH) == 1, "a field that fits: no map");
    CHECK(kiosk_map_levels_for(DW + 1, DH, DW, DH) == 2, "a texel wider: two levels");
    CHECK(kiosk_map_levels_for(DW, 4 * DH + 1, DW, DH) == 4, "taller: %d levels",
          kiosk_map_levels_for(DW, 4 * DH + 1, DW, DH));
}

/* The whole-field level (128 x 64) is one tile whose window is the level:
 * equal to a render of the twice-halved field (with its albedo map). */
static void whole_level(const world *w, hfs_renderer *r)
{
    world a = *w;
    float *alb = malloc(sizeof(float) * 3 * W * H);
    for (int p = 0; p < 3 * W * H; ++p)
        alb[p] = (float)((p * 2654435761u) % 1000u) / 1000.0f;
    a.in.lighting.albedo_map = alb;
    kiosk_map *m = new_map(&a);
    int vw, vh;
    kiosk_map_view_size(m, 3, &vw, &vh);
    CHECK(vw == W / 8 && vh == H / 8, "the whole level's view: %dx%d", vw, vh);
    kiosk_map_view_size(m, 0, &vw, &vh);
    CHECK(vw == DW && vh == DH, "level 0's view: the display's, %dx%d", vw, vh);
    hfs_image img = {0}, ref = {0};
    const kiosk_map_stats s = frame(m, r, &a, 0.0, 0.0, 3, &img);
    CHECK(s.rendered == 1 && s.cached == 1 && s.level == 3, "level 3: %d rendered, %d cached",
          s.rendered, s.cached);
    float *z = w->z, *al = alb;
    int lw = W, lh = H;
    for (int l = 0; l < 3; ++l) {
        float *hz = halve(z, lw, lh, 1), *ha = halve(al, lw, lh, 3);
        if (l)
            free(z), free(al);
        z = hz, al = ha, lw = (lw + 1) / 2, lh = (lh + 1) / 2;
    }
    const hfs_field f = {lw, lh, z, w->in.field.dx * 8, 1.0};
    hfs_lighting l = a.in.lighting;
    l.albedo_map = al;
    render(r, &f, &l, &a.in.quality, &ref);
    CHECK(same(&img, &ref), "level 3 == the render of the halved field and albedo");
    hfs_image_free(&img), hfs_image_free(&ref);
    free(z), free(al), free(alb);
    kiosk_map_free(m);
}

/* Level 0's view at (cx, cy), whose top left corner is (ox, oy) (a view
 * past the field's far corner is kept on it), against the crop of the
 * whole field's render: mean and max of the difference over the view, of
 * the render's maximum. */
static void against_whole(const world *w, hfs_renderer *r, const hfs_image *whole, double cx,
                          double cy, int ox, int oy, const double bound[2])
{
    kiosk_map *m = new_map(w);
    hfs_image img = {0};
    frame(m, r, w, cx, cy, 0, &img);
    const double mx = hfs_image_max(whole);
    double mean = 0.0, worst = 0.0;
    for (int j = 0; j < DH; ++j)
        for (int i = 0; i < DW * 3; ++i) {
            const double d = fabs((double)img.rgb[(size_t)j * DW * 3 + i] -
                                  whole->rgb[((size_t)(oy + j) * W + ox) * 3 + i]) / mx;
            mean += d / (3.0 * DW * DH);
            worst = fmax(worst, d);
        }
    printf("level 0 at (%g, %g) against the whole field: mean %.3g, max %.3g\n", cx, cy, mean,
           worst);
    CHECK(mean <= bound[0] && worst <= bound[1], "level 0 at (%g, %g): mean %g, max %g", cx, cy,
          mean, worst);
    hfs_image_free(&img);
    kiosk_map_free(m);
}

/* Texels beyond the halo of level 0's tiles of the first row that rise
 * eps (radians) or more above one of every 64th texel of their tile; the
 * halos printed. */
static int above_eps(const kiosk_map *m, const world *w, double eps)
{
    const double rise = tan(eps);
    int n = 0;
    for (int t = 0; t < 4; ++t) {
        const int ix = t * 256, iy = 0;
        const int h = kiosk_map_tile_halo(m, 0, ix, iy, 256, 256, eps);
        printf("%s%d", t ? " " : "level 0's tiles' halos: ", h);
        CHECK(h > 0 && h <= m->lv[0].halo && h % HFS_TILE_ALIGN == 0,
              "tile %d: halo %d (the level's %d)", t, h, m->lv[0].halo);
        for (int j = iy; j < iy + 256; j += 64)
            for (int i = ix; i < ix + 256; i += 64)
                for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x) {
                        if (x >= ix - h && x < ix + 256 + h && y >= iy - h && y < iy + 256 + h)
                            continue;
                        const double d = hypot(x - i, y - j) * w->in.field.dx;
                        n += w->z[y * W + x] - w->z[j * W + i] >= d * rise;
                    }
    }
    printf(" (the level's %d)\n", m->lv[0].halo);
    return n;
}

/* The halos of level 0's tiles: from every 32nd texel of a tile, no
 * texel beyond the halo's window rises eps above it; never wider than the
 * level's; a local light: the whole level. */
static void halo_checks(world *w)
{
    kiosk_map *m = new_map(w);
    const double eps = hfs_tile_eps(&w->in.lighting);
    int n = above_eps(m, w, eps);
    CHECK(n == 0, "%d texels beyond a halo rise above %g rad", n, eps);
    hfs_lighting l = w->in.lighting;
    l.n_local = 1;
    l.local[0] = (hfs_local_light){.pos = {300, 200, 100}, .radius = 5, .radiance = {1, 1, 1}};
    CHECK(kiosk_map_tile_halo(m, 0, 0, 0, 256, 256, hfs_tile_eps(&l)) == -1,
          "a local light: the whole level");
    kiosk_map_free(m);
    /* one peak, 300 m over a plain of 30 m cells, at (900, 450): the level
     * needs 464 texels; the tile at the far corner, 644 texels from the
     * top, sees it 0.9 deg up at most (< 1.27): it needs a small halo */
    world p = *w;
    p.z = calloc((size_t)W * H, sizeof *p.z);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            p.z[y * W + x] = (float)fmax(0.0, 300.0 - 8.0 * hypot(x - 900, y - 450));
    p.in.field.z = p.z;
    m = new_map(&p);
    const int far = kiosk_map_tile_halo(m, 0, 0, 0, 256, 256, eps);
    const int near = kiosk_map_tile_halo(m, 0, 768, 256, 256, 256, eps);
    printf("one peak: the far corner's halo %d, the peak's tile's %d, the level's %d\n", far,
           near, m->lv[0].halo);
    CHECK(far < 64 && near == m->lv[0].halo, "one peak: halos %d, %d (the level's %d)", far,
          near, m->lv[0].halo);
    n = above_eps(m, &p, eps);
    CHECK(n == 0, "one peak: %d texels beyond a halo rise above %g rad", n, eps);
    kiosk_map_free(m);
    free(p.z);
}

/* Every tile the view wants fetched ahead: how many, the cache within its
 * budget. */
static int fetch_all(kiosk_map *m, hfs_renderer *r, const world *w)
{
    hfs_error err = {""};
    int n = 0, rc;
    while ((rc = kiosk_map_prefetch(m, r, &w->in, &err)) > 0 && n < 1000)
        ++n;
    CHECK(rc == 0, "prefetch: %s", err.msg);
    kiosk_map_stats s;
    kiosk_map_stats_get(m, &s);
    CHECK(s.bytes <= s.budget, "the cache: %zu bytes over its budget of %zu", s.bytes, s.budget);
    return n;
}

/* Ahead of the pan and the zoom; then a relit world. */
static void ahead(world *w, hfs_renderer *r)
{
    kiosk_map *m = new_map(w);
    hfs_image img = {0};
    kiosk_map_stats s = frame(m, r, w, 300.0, 200.0, 0, &img);
    CHECK(s.rendered == 4, "the first view renders its 4 tiles: %d", s.rendered);
    /* the ring (tiles 2 of rows 0 and 1) and the view a level out (tile 0) */
    const int n = fetch_all(m, r, w);
    CHECK(n == 3, "fetched ahead: %d tiles (2 of the ring, 1 a level out)", n);
    s = frame(m, r, w, 300.0 + 256.0, 200.0, 0, &img); /* a tile east */
    CHECK(s.rendered == 0 && s.coarse == 0, "a pan of a tile: %d tiles rendered, %d coarse",
          s.rendered, s.coarse);
    CHECK(as_new(w, r, 556.0, 200.0, 0, &img), "panned view == a new map's");
    fetch_all(m, r, w);
    s = frame(m, r, w, 556.0, 200.0, 1, &img); /* a level out */
    CHECK(s.rendered == 0 && s.coarse == 0, "a zoom out: %d tiles rendered, %d coarse",
          s.rendered, s.coarse);
    fetch_all(m, r, w);
    s = frame(m, r, w, 556.0, 200.0, 0, &img); /* back in */
    CHECK(s.rendered == 0 && s.coarse == 0, "a zoom in: %d tiles rendered, %d coarse",
          s.rendered, s.coarse);
    /* relit: every tile dropped, the frame renders its own */
    w->in.lighting.key[0].elev = 20.0 * PI / 180.0;
    s = frame(m, r, w, 556.0, 200.0, 0, &img);
    CHECK(s.rendered == 4 && s.cached == 4, "relit: %d rendered, %d cached", s.rendered,
          s.cached);
    CHECK(as_new(w, r, 556.0, 200.0, 0, &img), "relit view == a new map's");
    w->in.lighting.key[0].elev = 12.0 * PI / 180.0;
    hfs_image_free(&img);
    kiosk_map_free(m);
}

/* A jump farther than the tiles ahead: shown at once from the coarser
 * level (each of its texels on 2x2), then sharpened tile by tile, each
 * tile of the view first (kiosk_map_prefetch says 2). */
static void coarse_first(const world *w, hfs_renderer *r)
{
    kiosk_map *m = new_map(w);
    hfs_image img = {0};
    frame(m, r, w, 300.0, 200.0, 1, &img);
    fetch_all(m, r, w); /* level 1's ring: every level-1 tile (2 x 1) */
    /* origin (820, 340): level 0's tile (3, 1), which nothing fetched */
    kiosk_map_stats s = frame(m, r, w, 900.0, 400.0, 0, &img);
    CHECK(s.rendered == 0 && s.coarse == 1, "a jump: %d rendered, %d coarse", s.rendered,
          s.coarse);
    int blocks = 1;
    for (int j = 0; j < DH; ++j)
        for (int i = 0; i < DW; i += 2)
            blocks &= !memcmp(&img.rgb[((size_t)j * DW + i) * 3],
                              &img.rgb[((size_t)(j & ~1) * DW + i + 1) * 3], 3 * sizeof(float));
    CHECK(blocks, "a coarse stand-in: every 2x2 block one level-1 texel");
    hfs_error err = {""};
    int views = 0, rc;
    while ((rc = kiosk_map_prefetch(m, r, &w->in, &err)) == 2)
        ++views;
    CHECK(views == 1 && rc >= 0, "the view's tile lit first: %d (%d)", views, rc);
    s = frame(m, r, w, 900.0, 400.0, 0, &img);
    CHECK(s.rendered == 0 && s.coarse == 0, "sharpened: %d rendered, %d coarse", s.rendered,
          s.coarse);
    CHECK(as_new(w, r, 900.0, 400.0, 0, &img), "sharpened view == a new map's");
    hfs_image_free(&img);
    kiosk_map_free(m);
}

int main(void)
{
    levels();
    hfs_renderer *r = cpu();
    world w;
    make_world(&w);
    halo_checks(&w);
    whole_level(&w, r);
    hfs_image whole = {0};
    render(r, &w.in.field, &w.in.lighting, &w.in.quality, &whole);
    against_whole(&w, r, &whole, 300.0, 200.0, 300 - DW / 2, 200 - DH / 2, bound_mid);
    against_whole(&w, r, &whole, 5000.0, 512.0, W - DW, H - DH, bound_corner); /* far corner */
    hfs_image_free(&whole);
    ahead(&w, r);
    coarse_first(&w, r);
    free(w.z);
    hfs_renderer_destroy(r);
    printf("%s: %ld checks, %d failures\n", failures ? "FAIL" : "PASS", checks, failures);
    return failures ? 1 : 0;
}
