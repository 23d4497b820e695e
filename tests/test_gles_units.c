/*
 * test_gles_units.c — the GLES renderer's driver-free parts (label "unit"):
 *
 *   caps    hfs_gl_caps_select on synthetic drivers: every profile's
 *           requirements refused with a one-line message naming what is
 *           missing; limits are min(driver, profile) (ES 3.0 minimums for
 *           es30-*, the driver's for es32); formats follow the precision.
 *   layout  hfs_gles_layout_init agrees with pyramid_layout.h for many sizes
 *           and k/o (level count, sizes, spacings, read levels) and defines
 *           the visibility grid as DESIGN.md says.
 *   split   the fp16 hi+lo upload represents every normalized height to
 *           2^-21 of the height range (measured bound) and is exact for a
 *           flat field.
 *   offsets the shader's float sample offsets classify every (direction,
 *           scale) sample like the CPU's double rule, for the default
 *           swaths at many sizes and for key swaths (DESIGN.md: same rule,
 *           float tolerance).
 *   blocks  the std140 swath block carries hfs_visibility_sample_matrix
 *           and the wedge placements; scales and output scale.
 *   bounds  the gap search's bounds round up (bounds_texture.h): each
 *           stored value is the least fp16 / float at or above the bound.
 */
#include "bounds_texture.h"
#include "cpu_pyramid.h"
#include "gl_caps.h"
#include "gl_util.h"
#include "uniform_blocks.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

#define CHECK_MAX_MESSAGES 30
#include "check.h"

static hfs_gl_driver llvmpipe_like(void)
{
    hfs_gl_driver d;
    memset(&d, 0, sizeof d);
    d.is_es = 1, d.major = 3, d.minor = 2;
    d.color_buffer_half_float = d.color_buffer_float = d.texture_float_linear = 1;
    d.float_blend = 1;
    d.timer_query = 1;
    d.max_texture_size = 16384;
    d.max_array_texture_layers = 2048;
    d.max_draw_buffers = 8;
    d.max_uniform_block_size = 65536;
    d.max_fragment_uniform_blocks = 24;
    d.max_uniform_buffer_bindings = 72;
    d.max_texture_image_units = 32;
    d.uniform_buffer_offset_alignment = 16;
    return d;
}

static void test_caps(void)
{
    hfs_gl_caps c;
    hfs_error err;
    hfs_gl_driver d = llvmpipe_like();

    /* Default: the profile's features, the driver's limits (issue 13). */
    CHECK(hfs_gl_caps_select(&d, NULL, 0, 0, &c, &err) == 0, "default: %s", err.msg);
    CHECK(!strcmp(c.profile, "es30-half") && !c.fp32 && c.fmt_rg == GL_RG16F &&
              c.fmt_rgba == GL_RGBA16F && c.type_upload == GL_HALF_FLOAT,
          "default profile/formats");
    CHECK(c.max_texture_size == 16384 && c.max_uniform_block_size == 65536 && !c.strict_limits,
          "es30 default limits are not the driver's: %d %d", c.max_texture_size,
          c.max_uniform_block_size);
    CHECK(hfs_gl_caps_check_texture(&c, 4096, 4096, 1, "field", &err) == 0,
          "a 4096^2 field on a 16384 driver: %s", err.msg);
    CHECK(hfs_gl_caps_check_uniform_block(&c, 70000, "swath (lower --nphi-key)", &err) ==
                  HFS_E_UNSUPPORTED &&
              strstr(err.msg, "the driver's limit 65536 (GL_MAX_UNIFORM_BLOCK_SIZE)") &&
              strstr(err.msg, "70000") && strstr(err.msg, "--nphi-key"),
          "refusal names the limit, the value and the way out: %s", err.msg);

    /* Strict limits (CI): the ES 3.0 minimums. */
    CHECK(hfs_gl_caps_select(&d, NULL, 0, 1, &c, &err) == 0 && c.strict_limits, "strict: %s",
          err.msg);
    CHECK(hfs_gl_caps_check_texture(&c, 4096, 4096, 1, "field", &err) == HFS_E_UNSUPPORTED &&
              strstr(err.msg, "the ES 3.0 minimum 2048 (GL_MAX_TEXTURE_SIZE, strict limits; "
                              "this driver allows 16384)"),
          "strict refusal: %s", err.msg);
    CHECK(c.max_texture_size == 2048 && c.max_array_texture_layers == 256 &&
              c.max_draw_buffers == 4 && c.max_uniform_block_size == 16384 &&
              c.max_texture_image_units == 16 && c.uniform_buffer_offset_alignment == 256,
          "es30 limits not capped at the ES 3.0 minimums: %d %d %d %d %d %d", c.max_texture_size,
          c.max_array_texture_layers, c.max_draw_buffers, c.max_uniform_block_size,
          c.max_texture_image_units, c.uniform_buffer_offset_alignment);
    CHECK(c.driver.max_texture_size == 16384, "driver values not kept");

    CHECK(hfs_gl_caps_select(&d, NULL, 1, 1, &c, &err) == 0 && !strcmp(c.profile, "es30-float") &&
              c.fp32 && c.fmt_rg == GL_RG32F && c.fmt_rgba == GL_RGBA32F && c.type_upload == GL_FLOAT,
          "fp32 default profile: %s", err.msg);
    CHECK(hfs_gl_caps_select(&d, "es32", 0, 1, &c, &err) == 0 && c.max_texture_size == 16384 &&
              c.max_uniform_block_size == 65536 && c.max_draw_buffers == 8 && !c.fp32,
          "es32 must keep the driver's limits: %s", err.msg);
    CHECK(hfs_gl_caps_select(&d, "es32", 1, 1, &c, &err) == 0 && c.fp32, "es32 fp32: %s", err.msg);

    /* A driver smaller than the profile: min wins. */
    hfs_gl_driver small = d;
    small.max_texture_size = 1024;
    small.max_uniform_block_size = 8192;
    CHECK(hfs_gl_caps_select(&small, "es30-half", 0, 1, &c, &err) == 0 && c.max_texture_size == 1024 &&
              c.max_uniform_block_size == 8192, "small driver");

    /* Refusals, each one line naming what is missing. */
    struct {
        const char *profile;
        int fp32;
        void (*edit)(hfs_gl_driver *);
        int code;
        const char *needle;
    } cases[] = {
        {"es30-half", 0, NULL, 0, NULL},
        {"es29", 0, NULL, HFS_E_INVALID, "es30-half, es30-float, es32"},
        {"es30-half", 1, NULL, HFS_E_UNSUPPORTED, "es30-float"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        int rc = hfs_gl_caps_select(&d, cases[i].profile, cases[i].fp32, 1, &c, &err);
        CHECK(rc == cases[i].code, "case %zu: rc %d", i, rc);
        if (cases[i].needle)
            CHECK(strstr(err.msg, cases[i].needle) && !strchr(err.msg, '\n'), "case %zu: %s", i,
                  err.msg);
    }
    hfs_gl_driver nohalf = d;
    nohalf.minor = 0;
    nohalf.color_buffer_half_float = nohalf.color_buffer_float = 0;
    int rc = hfs_gl_caps_select(&nohalf, NULL, 0, 1, &c, &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_EXT_color_buffer_half_float"),
          "no half-float targets: %d %s", rc, err.msg);
    hfs_gl_driver half_only = d;
    half_only.minor = 0;
    half_only.color_buffer_float = 0;
    CHECK(hfs_gl_caps_select(&half_only, NULL, 0, 1, &c, &err) == 0, "ES 3.0 + half: %s", err.msg);
    rc = hfs_gl_caps_select(&half_only, NULL, 1, 1, &c, &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_EXT_color_buffer_float"),
          "fp32 without float targets: %d %s", rc, err.msg);
    rc = hfs_gl_caps_select(&half_only, "es32", 0, 1, &c, &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "es32"), "es32 on ES 3.0: %d %s", rc, err.msg);
    hfs_gl_driver nolinear = d;
    nolinear.texture_float_linear = 0;
    rc = hfs_gl_caps_select(&nolinear, NULL, 1, 1, &c, &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_OES_texture_float_linear"),
          "fp32 without float filtering: %d %s", rc, err.msg);
    CHECK(hfs_gl_caps_select(&nolinear, NULL, 0, 1, &c, &err) == 0, "fp16 needs no float filtering");
    hfs_gl_driver noblend = d;
    noblend.float_blend = 0;
    CHECK(hfs_gl_caps_select(&noblend, NULL, 1, 1, &c, &err) == 0 && c.fmt_r == GL_R32F,
          "no blending is needed: %s", err.msg);
    hfs_gl_driver desktop = d;
    desktop.is_es = 0, desktop.major = 4, desktop.minor = 5;
    CHECK(hfs_gl_caps_select(&desktop, "es32", 1, 1, &c, &err) == 0, "desktop GL: %s", err.msg);

    /* Checks. */
    CHECK(hfs_gl_caps_select(&d, NULL, 0, 1, &c, &err) == 0, "reselect");
    CHECK(hfs_gl_caps_check_texture(&c, 2048, 2048, 256, "x", &err) == 0, "2048^2 x 256 fits");
    rc = hfs_gl_caps_check_texture(&c, 2049, 16, 1, "height levels", &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_MAX_TEXTURE_SIZE") &&
              strstr(err.msg, "height levels"), "texture size: %s", err.msg);
    rc = hfs_gl_caps_check_texture(&c, 16, 16, 257, "layers", &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_MAX_ARRAY_TEXTURE_LAYERS"), "layers: %s",
          err.msg);
    rc = hfs_gl_caps_check_uniform_block(&c, 16385, "swath", &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_MAX_UNIFORM_BLOCK_SIZE"), "ubo: %s",
          err.msg);
    CHECK(hfs_gl_caps_check_uniform_block(&c, 16384, "swath", &err) == 0, "16384-byte block fits");
    rc = hfs_gl_caps_check_draw_buffers(&c, 5, "mrt", &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_MAX_DRAW_BUFFERS"), "mrt: %s", err.msg);
    rc = hfs_gl_caps_check_samplers(&c, 17, "shade", &err);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_MAX_TEXTURE_IMAGE_UNITS"), "units: %s",
          err.msg);
}

static void test_layout(void)
{
    static const int sizes[][2] = {{2, 2}, {3, 7}, {37, 20}, {64, 64}, {96, 96}, {100, 33},
                                   {255, 256}, {256, 256}, {403, 344}, {512, 512}, {1000, 3}};
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; ++si)
        for (int k = 1; k <= 8; k *= 2)
            for (int o = 0; o <= 3; ++o)
                for (int sub = 1; sub <= 4; sub *= 2) {
                    const int w = sizes[si][0], h = sizes[si][1];
                    float *z = calloc((size_t)w * h, sizeof *z);
                    hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
                    hfs_quality q;
                    hfs_quality_defaults(&q);
                    q.k = k, q.offset = o, q.subsample = sub;
                    hfs_gles_layout L;
                    hfs_error err;
                    CHECK(hfs_gles_layout_init(&L, &f, &q, &err) == 0, "layout: %s", err.msg);
                    const int n = hfs_pyramid_level_count(w, h, k);
                    CHECK(L.n_levels == n, "%dx%d k%d: %d levels, cpu %d", w, h, k, L.n_levels, n);
                    CHECK(L.lmin == hfs_pyramid_read_level(n, k, o, 0) &&
                              L.n_layers == n - L.lmin, "read range");
                    for (int i = 0; i < n; ++i) {
                        int lw, lh;
                        hfs_pyramid_level_size(w, h, k, i, &lw, &lh);
                        CHECK(L.lw[i] == lw && L.lh[i] == lh, "level %d size", i);
                        CHECK(L.spacing[i] == hfs_pyramid_spacing(n, k, i), "spacing %d", i);
                        CHECK(L.read_layer[i] + L.lmin == hfs_pyramid_read_level(n, k, o, i),
                              "read level %d", i);
                    }
                    /* Grid: receiver a at min(a*sub, W-1); the last one at W-1. */
                    CHECK((L.vw - 1) * sub >= w - 1 && (L.vw - 2) * sub < w - 1, "%dx%d sub %d: vw %d",
                          w, h, sub, L.vw);
                    CHECK((L.vh - 1) * sub >= h - 1 && (L.vh - 2) * sub < h - 1, "vh %d", L.vh);
                    CHECK(L.vmax == 0.0 && L.hscale == 1.0, "flat field normalization");
                    free(z);
                }
}

/* Field f's layout at the default quality. */
static void default_layout(const hfs_field *f, hfs_gles_layout *L)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_error err;
    hfs_gles_layout_init(L, f, &q, &err);
}

static void test_split(void)
{
    const int w = 300, h = 211;
    float *z = malloc((size_t)w * h * sizeof *z);
    uint16_t *pairs = malloc((size_t)w * h * 2 * sizeof *pairs);
    float *f32 = malloc((size_t)w * h * 2 * sizeof *f32);
    unsigned s = 12345u;
    static const double ranges[][2] = {{236.0, 1076.0}, {0.0, 1.0}, {-5e4, 7e4}, {1e6, 1e6 + 3.0}};
    for (size_t ri = 0; ri < 4; ++ri) {
        for (size_t i = 0; i < (size_t)w * h; ++i) {
            s = s * 1103515245u + 12345u;
            z[i] = (float)(ranges[ri][0] + (ranges[ri][1] - ranges[ri][0]) * ((s >> 8) / 16777216.0));
        }
        z[0] = (float)ranges[ri][0];
        z[1] = (float)ranges[ri][1];
        hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
        hfs_gles_layout L;
        default_layout(&f, &L);
        const double e = hfs_gles_split_heights(&L, &f, 0, pairs, 1);
        double worst = 0.0, vmax = 0.0;
        for (size_t i = 0; i < (size_t)w * h; ++i) {
            const double v = hfs_half_to_float(pairs[2 * i]) + (double)hfs_half_to_float(pairs[2 * i + 1]);
            const double zz = L.base + L.hscale * v;
            worst = fmax(worst, fabs(zz - z[i]) / (2.0 * L.hscale));
            vmax = fmax(vmax, fabs(v));
        }
        printf("split range [%g, %g]: max error %.3e of the range (reported %.3e normalized)\n",
               ranges[ri][0], ranges[ri][1], worst, e);
        CHECK(worst <= ldexp(1.0, -21), "hi+lo error %.3e > 2^-21 of the range", worst);
        CHECK(vmax <= 1.0 + 1e-6, "normalized height %.9f outside [-1, 1]", vmax);
        CHECK(hfs_gles_split_heights(&L, &f, 1, f32, 1) == 0.0 && f32[1] == 0.0f, "fp32 split");
    }
    for (size_t i = 0; i < (size_t)w * h; ++i)
        z[i] = 812.25f;
    hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_gles_layout L;
    default_layout(&f, &L);
    CHECK(hfs_gles_split_heights(&L, &f, 0, pairs, 1) == 0.0 && pairs[0] == 0 && pairs[1] == 0,
          "flat field must be exactly 0");
    free(z);
    free(pairs);
    free(f32);
}

static void test_offsets(void)
{
    long total = 0;
    for (int n = 2; n <= 1100; n += (n < 70 ? 1 : 37)) {
        for (int k = 1; k <= 8; k *= 2) {
            float z[4] = {0};
            hfs_field f = {.width = n, .height = n, .z = z, .dx = 1.0, .zscale = 1.0};
            hfs_quality q;
            hfs_quality_defaults(&q);
            q.k = k;
            hfs_gles_layout L;
            hfs_error err;
            /* layout_init reads z for the range: give it a 2x2 view. */
            hfs_field tiny = {.width = 2, .height = 2, .z = z, .dx = 1.0, .zscale = 1.0};
            hfs_gles_layout_init(&L, &tiny, &q, &err);
            L.w = L.h = n;
            L.n_levels = hfs_pyramid_level_count(n, n, k);
            for (int i = 0; i < L.n_levels; ++i)
                L.spacing[i] = hfs_pyramid_spacing(L.n_levels, k, i);
            static const int nphis[] = {3, 8, 16, 32, 48, 64};
            for (size_t a = 0; a < sizeof nphis / sizeof nphis[0]; ++a) {
                hfs_swath s;
                hfs_swath_full(nphis[a], &s);
                const long bad = hfs_gles_offset_mismatches(&L, &s);
                CHECK(bad == 0, "n %d k %d nphi %d: %ld samples classified differently", n, k,
                      nphis[a], bad);
                total += bad;
            }
            for (int e = 0; e < 90; e += 15) {
                hfs_swath s;
                hfs_swath_key(336.0 * PI / 180.0, e * PI / 180.0, 2.0 * PI / 180.0, 3, 32, &s);
                total += hfs_gles_offset_mismatches(&L, &s);
            }
            (void)f;
        }
    }
    printf("offsets: %ld mismatching samples over all configurations\n", total);
}

static void test_blocks(void)
{
    hfs_swath s;
    hfs_swath_key(1.0, 0.3, 0.05, 3, 32, &s);
    hfs_visibility *v = NULL;
    hfs_error err;
    CHECK(hfs_visibility_create(&s, HFS_VIS_LEGENDRE, &v, &err) == 0, "vis: %s", err.msg);
    if (!v)
        return;
    const size_t nv = hfs_gles_swath_vec4(s.n);
    CHECK(s.n >= 3 && nv == 2 + 17 * (size_t)s.n + 2 * (size_t)(s.n + 1), "swath block size %zu",
          nv);
    float *b = calloc(nv * 4, sizeof *b);
    hfs_gles_layout Lb;
    {
        float zz[4] = {0};
        hfs_field fb = {.width = 2, .height = 2, .z = zz, .dx = 1.0, .zscale = 1.0};
        hfs_quality qb;
        hfs_quality_defaults(&qb);
        hfs_gles_layout_init(&Lb, &fb, &qb, &err);
    }
    hfs_gles_pack_swath(&Lb, v, b);
    CHECK(b[0] == (float)s.elev_lo && b[1] == (float)s.elev_hi && b[2] == (float)s.n &&
              b[3] == 0.0f,
          "header");
    for (int j = 0; j < s.n; ++j) {
        const double *m = hfs_visibility_sample_matrix(v, j);
        for (int r = 0; r < 16; ++r)
            for (int c = 0; c < 4; ++c)
                CHECK(b[(2 + s.n + 16 * j + r) * 4 + c] == (float)m[r * 4 + c], "C_%d[%d][%d]", j, r,
                      c);
        double c0, s0;
        hfs_gles_swath_dir(&s, j, &c0, &s0);
        CHECK(fabs(b[(2 + j) * 4] - c0) < 1e-5 && fabs(b[(2 + j) * 4 + 1] - s0) < 1e-5, "dir %d", j);
    }
    /* Wedge placements: start boundary mirrored at phi_0, end at phi_{n-1}. */
    const float *rot = b + (2 + 17 * (size_t)s.n) * 4;
    CHECK(rot[3] == 1.0f && rot[8 + 3] == 0.0f, "mirror flags");
    CHECK(fabs(rot[0] - cos(hfs_swath_phi(&s, 0))) < 1e-6, "start boundary angle");
    CHECK(fabs(rot[s.n * 8] - cos(hfs_swath_phi(&s, s.n - 1))) < 1e-6, "end boundary angle");
    free(b);
    hfs_visibility_destroy(v);

    /* Scales: d_i, inv_run_i, layer. */
    float z[4] = {0, 1, 2, 3};
    hfs_field f = {.width = 2, .height = 2, .z = z, .dx = 2.0, .zscale = 3.0};
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_gles_layout L;
    hfs_gles_layout_init(&L, &f, &q, &err);
    /* The head: N as an int; then the scales; zeros past N. */
    CHECK(hfs_gles_scales_vec4() == 1 + HFS_GLES_MAX_LEVELS, "scales block size");
    float sc[4 * (1 + HFS_GLES_MAX_LEVELS)];
    memset(sc, 0xff, sizeof sc);
    hfs_gles_pack_scales(&L, sc);
    int32_t head[4];
    memcpy(head, sc, sizeof head);
    CHECK(head[0] == L.n_levels && L.n_levels >= 1 && !head[1] && !head[2] && !head[3],
          "scales head: %d scales", head[0]);
    for (int i = 0; i < L.n_levels; ++i)
        CHECK(sc[4 + 4 * i] == (float)L.spacing[i] &&
                  fabs(sc[4 + 4 * i + 1] - L.hscale * 3.0 / (L.spacing[i] * 2.0)) < 1e-6 &&
                  sc[4 + 4 * i + 2] == (float)L.read_layer[i] && sc[4 + 4 * i + 3] == 0.0f,
              "scale %d", i);
    for (int i = 4 + 4 * L.n_levels; i < 4 * (1 + HFS_GLES_MAX_LEVELS); ++i)
        CHECK(sc[i] == 0.0f, "scales: zero past N at float %d", i);
    CHECK(hfs_gles_output_scale(1.0) == 16384.0 && hfs_gles_output_scale(1e6) == 1.0 / 64.0 &&
              hfs_gles_output_scale(0.0) == 1.0, "output scale");
    /* A local light's largest irradiance over the field's box [0, 2]^2 x
     * [0, 9 + 2e-4]: pi (r/d_min)^2 outside, pi once it reaches the box. */
    const hfs_local_light far = {.pos = {1.0, 1.0, 19.0002}, .radius = 1.0};
    const hfs_local_light in = {.pos = {1.0, 1.0, 5.0}, .radius = 0.1};
    const hfs_local_light touch = {.pos = {5.0, 1.0, 4.0}, .radius = 3.0};
    CHECK(fabs(hfs_gles_local_max_irradiance(&L, &far) - PI / 100.0) < 1e-12 &&
              hfs_gles_local_max_irradiance(&L, &in) == PI &&
              hfs_gles_local_max_irradiance(&L, &touch) == PI, "local max irradiance");
}

/* A field large enough for the split's worker threads (layout.c
 * SPLIT_THREADED) gives the bits and the error of one pass over it. */
static void test_split_threaded(void)
{
    const int w = 701, h = 401;
    const size_t n = (size_t)w * h;
    float *z = malloc(n * sizeof *z);
    uint16_t *a = malloc(n * 2 * sizeof *a), *b = malloc(n * 2 * sizeof *b);
    if (!z || !a || !b) {
        CHECK(0, "split threaded: out of memory");
        free(z), free(a), free(b);
        return;
    }
    unsigned s = 777u;
    for (size_t i = 0; i < n; ++i) {
        s = s * 1103515245u + 12345u;
        z[i] = (float)(100.0 + 900.0 * ((s >> 8) / 16777216.0));
    }
    hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_gles_layout L;
    default_layout(&f, &L);
    const double e = hfs_gles_split_heights(&L, &f, 0, a, 1);
    const double want = hfs_half_split(z, n, L.base, L.hscale, b, 1);
    CHECK(memcmp(a, b, n * 2 * sizeof *a) == 0 && e == want,
          "split threaded: differs from one pass (error %.3e, want %.3e)", e, want);
    free(z), free(a), free(b);
}

/* Every stored bound is at or above its value, and the next value down
 * is below it (the least such), in fp16 and float, over many magnitudes
 * and both signs. */
static void test_bounds(void)
{
    unsigned x = 2463534242u;
    int bad = 0;
    for (int t = 0; t < 200000; ++t) {
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        const double v = ((x & 1u) ? -1.0 : 1.0) * ldexp((double)(x >> 8) / 16777216.0,
                                                          (int)(x % 40u) - 30);
        const uint16_t h = hfs_gles_half_up(v);
        const double hv = hfs_half_to_float(h);
        const uint16_t below = hv > 0.0 ? (uint16_t)(h - 1u) : (uint16_t)(h + 1u);
        bad += !(hv >= v) || (hv != 0.0 && !((double)hfs_half_to_float(below) < v));
        const float f = hfs_gles_float_up(v);
        bad += !((double)f >= v) || !((double)nextafterf(f, -INFINITY) < v);
    }
    CHECK(bad == 0, "bounds: %d values not rounded up to the least value above", bad);
    CHECK(hfs_half_to_float(hfs_gles_half_up(0.0)) == 0.0f &&
              hfs_half_to_float(hfs_gles_half_up(-2.0)) == -2.0f,
          "bounds: exact values kept");
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    test_bounds();
    test_caps();
    test_layout();
    test_split();
    test_split_threaded();
    test_offsets();
    test_blocks();
    if (failures) {
        fprintf(stderr, "test_gles_units: %d check(s) failed\n", failures);
        return 1;
    }
    printf("test_gles_units: all checks passed\n");
    return 0;
}
