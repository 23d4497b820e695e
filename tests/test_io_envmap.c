/*
 * test_io_envmap.c — environment map loaders.
 *   Radiance .hdr written by stb_image_write (RLE for widths 8..32767, flat
 *   otherwise): values within RGBE precision, top row first, and every proper
 *   prefix of the file rejected as truncated (stb itself would decode zeros).
 *   OpenEXR written here with OpenEXRCore: scanline and tiled, half / float /
 *   uint, six lossless compressions, Y-only grey, extra A channel, an offset
 *   data window; exact round trips; NaN pixels, cube maps, partial RGB and
 *   every proper prefix rejected.
 *   PFM (PF and Pf) written by hfs_pfm_write: exact round trips, first row
 *   = top row, a NaN named by its pixel, a mislabelled .pfm, prefixes.
 */
#include "hfs_io.h"
#include "test_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <openexr.h>
#include <stb_image_write.h>

static int load_fails_cleanly(const char *path)
{
    hfs_envmap m;
    hfs_error err;
    int rc;
    memset(&m, 0x5a, sizeof m);
    err.msg[0] = '\0';
    rc = hfs_envmap_load(path, &m, &err);
    if (rc == 0) {
        hfs_envmap_free(&m);
        return 0;
    }
    return strstr(err.msg, path) == err.msg && !strchr(err.msg, '\n') && m.rgb == NULL &&
           m.width == 0 && m.height == 0;
}

/* Every proper prefix of a valid file must fail with a clean message. */
static void check_prefixes(const char *path, size_t step)
{
    size_t n;
    unsigned char *b = read_all(path, &n);
    int bad = 0;
    CHECK(b != NULL);
    if (!b)
        return;
    for (size_t len = 0; len < n; len += (len + step < n ? step : 1)) {
        write_bytes(tpath("prefix"), b, len);
        if (!load_fails_cleanly(tpath("prefix"))) {
            if (!bad++)
                fprintf(stderr, "  prefix %zu/%zu of %s loaded or failed badly\n", len, n, path);
        }
    }
    CHECK(bad == 0);
    free(b);
}

/* ---- Radiance ---------------------------------------------------------------------- */

static void test_hdr(void)
{
    static const int widths[] = {3, 8, 40};
    for (size_t t = 0; t < sizeof widths / sizeof widths[0]; ++t) {
        int w = widths[t], h = 5;
        float *px = malloc((size_t)w * h * 3 * sizeof *px);
        hfs_envmap m;
        hfs_error err;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                float *p = px + ((size_t)j * w + i) * 3;
                p[0] = (float)(j + 1) * 0.5f + (float)i * 0.01f;
                p[1] = i == w / 2 ? 0.0f : 0.125f * (float)(i % 4);
                p[2] = (float)(j * 100 + 1);
            }
        CHECK(stbi_write_hdr(tpath("m.hdr"), w, h, 3, px) != 0);
        CHECK(hfs_envmap_load(tpath("m.hdr"), &m, &err) == 0);
        CHECK(m.width == w && m.height == h);
        for (size_t k = 0; m.rgb && k < (size_t)w * h * 3; ++k) {
            /* RGBE keeps 8 mantissa bits of the pixel's largest channel. */
            float tol = fmaxf(fmaxf(px[k / 3 * 3], px[k / 3 * 3 + 1]), px[k / 3 * 3 + 2]) / 128.0f;
            CHECK(fabsf(m.rgb[k] - px[k]) <= tol);
        }
        /* Top row of the file (first written) is row 0. */
        CHECK(m.rgb && m.rgb[2] < 2.0f && m.rgb[((size_t)(h - 1) * w) * 3 + 2] > 300.0f);
        hfs_envmap_free(&m);
        check_prefixes(tpath("m.hdr"), 1);
        free(px);
    }

    /* Header checks stb would not explain. */
    {
        static const char *const bad[] = {
            "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 2\n",
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 2 +X 2\n",
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 200000 +X 2\n",
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 2\n",
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y -2 +X 2\n",
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X\n",
            "#?RADIANCE\n\n-Y 2 +X 2\n",
            "#?NOTHDR\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n",
        };
        for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
            write_bytes(tpath("bad.hdr"), bad[k], strlen(bad[k]));
            CHECK(load_fails_cleanly(tpath("bad.hdr")));
        }
    }
}

/* ---- OpenEXR --------------------------------------------------------------------------- */

static void exr_quiet(exr_const_context_t c, exr_result_t code, const char *msg)
{
    (void)c;
    fprintf(stderr, "  (openexr writer: %d %s)\n", (int)code, msg);
}

typedef struct exr_spec {
    int w, h, dx, dy;          /* size and data window origin */
    int tile;                  /* 0 = scanline */
    exr_compression_t comp;
    exr_pixel_type_t type;
    int nch;
    const char *names[4];
    int cube;
} exr_spec;

/* planes: one w*h float plane per channel, in names[] order. */
static int exr_write(const char *path, const exr_spec *s, float *const *planes)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t c = NULL;
    exr_encode_pipeline_t enc;
    exr_chunk_info_t ci;
    exr_attr_box2i_t dw;
    int part = 0, live = 0, ok = 1;
    int32_t lpc = 1;

    memset(&enc, 0, sizeof enc);
    init.error_handler_fn = exr_quiet;
    if (exr_start_write(&c, path, EXR_WRITE_FILE_DIRECTLY, &init))
        return -1;
    ok &= exr_add_part(c, "main", s->tile ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE, &part) == 0;
    ok &= exr_initialize_required_attr_simple(c, part, s->w, s->h, s->comp) == 0;
    dw.min.x = s->dx, dw.min.y = s->dy, dw.max.x = s->dx + s->w - 1, dw.max.y = s->dy + s->h - 1;
    ok &= exr_set_data_window(c, part, &dw) == 0;
    if (s->tile)
        ok &= exr_set_tile_descriptor(c, part, (uint32_t)s->tile, (uint32_t)s->tile,
                                      EXR_TILE_ONE_LEVEL, EXR_TILE_ROUND_DOWN) == 0;
    if (s->cube)
        ok &= exr_attr_set_envmap(c, part, "envmap", EXR_ENVMAP_CUBE) == 0;
    for (int k = 0; k < s->nch; ++k)
        ok &= exr_add_channel(c, part, s->names[k], s->type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1) == 0;
    ok &= exr_write_header(c) == 0;
    if (!s->tile)
        ok &= exr_get_scanlines_per_chunk(c, part, &lpc) == 0;

    for (int ty = 0; ok && ty * (s->tile ? s->tile : lpc) < s->h; ++ty) {
        int ntx = s->tile ? (s->w + s->tile - 1) / s->tile : 1;
        for (int tx = 0; ok && tx < ntx; ++tx) {
            int x0, y0;
            if (s->tile) {
                ok &= exr_write_tile_chunk_info(c, part, tx, ty, 0, 0, &ci) == 0;
                x0 = tx * s->tile, y0 = ty * s->tile;
            } else {
                ok &= exr_write_scanline_chunk_info(c, part, s->dy + ty * lpc, &ci) == 0;
                x0 = 0, y0 = ci.start_y - s->dy;
            }
            if (!ok)
                break;
            ok &= (live ? exr_encoding_update(c, part, &ci, &enc)
                        : exr_encoding_initialize(c, part, &ci, &enc)) == 0;
            live = 1;
            for (int ch = 0; ok && ch < enc.channel_count; ++ch) {
                int k = 0;
                while (k < s->nch && strcmp(s->names[k], enc.channels[ch].channel_name))
                    ++k;
                enc.channels[ch].encode_from_ptr =
                    (const uint8_t *)(planes[k] + (size_t)y0 * s->w + x0);
                enc.channels[ch].user_pixel_stride = 4;
                enc.channels[ch].user_line_stride = s->w * 4;
                enc.channels[ch].user_data_type = EXR_PIXEL_FLOAT;
                enc.channels[ch].user_bytes_per_element = 4;
            }
            ok &= exr_encoding_choose_default_routines(c, part, &enc) == 0;
            ok &= exr_encoding_run(c, part, &enc) == 0;
        }
    }
    if (live)
        exr_encoding_destroy(c, &enc);
    ok &= exr_finish(&c) == 0;
    return ok ? 0 : -1;
}

/* Values exact in half: multiples of 1/8 up to a few thousand, negatives. */
static float sample(int ch, int i, int j)
{
    return (float)((ch + 1) * 64 + j * 16 + i) * 0.125f - 10.0f;
}

static void test_exr_roundtrips(void)
{
    static const exr_compression_t comps[] = {EXR_COMPRESSION_NONE, EXR_COMPRESSION_RLE,
                                              EXR_COMPRESSION_ZIPS, EXR_COMPRESSION_ZIP,
                                              EXR_COMPRESSION_PIZ,  EXR_COMPRESSION_PXR24};
    exr_spec specs[16];
    int ns = 0;

    for (size_t k = 0; k < sizeof comps / sizeof comps[0]; ++k) {
        exr_spec s = {11, 37, 0, 0, 0, comps[k], EXR_PIXEL_HALF, 3, {"R", "G", "B", NULL}, 0};
        specs[ns++] = s;
    }
    {
        exr_spec s1 = {13, 9, 0, 0, 4, EXR_COMPRESSION_ZIP, EXR_PIXEL_FLOAT, 4, {"A", "B", "G", "R"}, 0};
        exr_spec s2 = {6, 5, -3, 7, 0, EXR_COMPRESSION_NONE, EXR_PIXEL_FLOAT, 1, {"Y"}, 0};
        exr_spec s3 = {9, 4, 2, -5, 0, EXR_COMPRESSION_ZIPS, EXR_PIXEL_UINT, 3, {"B", "R", "G"}, 0};
        exr_spec s4 = {17, 33, 0, 0, 16, EXR_COMPRESSION_PIZ, EXR_PIXEL_HALF, 3, {"R", "G", "B"}, 0};
        specs[ns++] = s1;
        specs[ns++] = s2;
        specs[ns++] = s3;
        specs[ns++] = s4;
    }

    for (int t = 0; t < ns; ++t) {
        const exr_spec *s = &specs[t];
        float *planes[4];
        hfs_envmap m;
        hfs_error err;
        char name[32];
        int rc;
        snprintf(name, sizeof name, "rt%d.exr", t);
        for (int k = 0; k < s->nch; ++k) {
            planes[k] = malloc((size_t)s->w * s->h * sizeof(float));
            for (int j = 0; j < s->h; ++j)
                for (int i = 0; i < s->w; ++i) {
                    /* Channel value keyed by name so the order in the file
                     * does not matter. */
                    int ch = s->names[k][0] == 'R' || s->names[k][0] == 'Y' ? 0
                           : s->names[k][0] == 'G' ? 1 : s->names[k][0] == 'B' ? 2 : 3;
                    float v = sample(ch, i, j);
                    planes[k][(size_t)j * s->w + i] = s->type == EXR_PIXEL_UINT ? (float)(ch * 1000 + j * s->w + i) : v;
                }
        }
        CHECK(exr_write(tpath(name), s, planes) == 0);
        rc = hfs_envmap_load(tpath(name), &m, &err);
        if (rc)
            fprintf(stderr, "  %s: %s\n", name, err.msg);
        CHECK(rc == 0);
        CHECK(m.width == s->w && m.height == s->h);
        for (int j = 0; rc == 0 && j < s->h; ++j)
            for (int i = 0; i < s->w; ++i)
                for (int c = 0; c < 3; ++c) {
                    int ch = s->nch == 1 ? 0 : c;
                    float want = s->type == EXR_PIXEL_UINT ? (float)(ch * 1000 + j * s->w + i)
                                                           : sample(ch, i, j);
                    if (m.rgb[((size_t)j * s->w + i) * 3 + c] != want) {
                        fprintf(stderr, "  %s (%d,%d,%d): %g != %g\n", name, i, j, c,
                                (double)m.rgb[((size_t)j * s->w + i) * 3 + c], (double)want);
                        CHECK(0);
                        j = s->h, i = s->w, c = 3;
                    }
                }
        hfs_envmap_free(&m);
        if (t == 0 || t == ns - 1 || t == ns - 4)
            check_prefixes(tpath(name), 1);
        for (int k = 0; k < s->nch; ++k)
            free(planes[k]);
    }
}

static void test_exr_refusals(void)
{
    float p0[16], p1[16], p2[16];
    float *planes[3] = {p0, p1, p2};
    for (int k = 0; k < 16; ++k)
        p0[k] = p1[k] = p2[k] = 1.0f;

    {   /* NaN and Inf are errors, not clamped. */
        exr_spec s = {4, 4, 0, 0, 0, EXR_COMPRESSION_NONE, EXR_PIXEL_FLOAT, 3, {"R", "G", "B"}, 0};
        p1[5] = NAN;
        CHECK(exr_write(tpath("nan.exr"), &s, planes) == 0);
        CHECK(load_fails_cleanly(tpath("nan.exr")));
        p1[5] = INFINITY;
        CHECK(exr_write(tpath("inf.exr"), &s, planes) == 0);
        CHECK(load_fails_cleanly(tpath("inf.exr")));
        p1[5] = 1.0f;
    }
    {   /* Cube-face maps. */
        exr_spec s = {4, 4, 0, 0, 0, EXR_COMPRESSION_NONE, EXR_PIXEL_HALF, 3, {"R", "G", "B"}, 1};
        CHECK(exr_write(tpath("cube.exr"), &s, planes) == 0);
        CHECK(load_fails_cleanly(tpath("cube.exr")));
    }
    {   /* Partial RGB, no usable channel. */
        exr_spec s = {4, 4, 0, 0, 0, EXR_COMPRESSION_NONE, EXR_PIXEL_HALF, 2, {"R", "G"}, 0};
        exr_spec z = {4, 4, 0, 0, 0, EXR_COMPRESSION_NONE, EXR_PIXEL_HALF, 1, {"Z"}, 0};
        CHECK(exr_write(tpath("rg.exr"), &s, planes) == 0);
        CHECK(load_fails_cleanly(tpath("rg.exr")));
        CHECK(exr_write(tpath("z.exr"), &z, planes) == 0);
        CHECK(load_fails_cleanly(tpath("z.exr")));
    }
    /* Not an environment map at all. */
    write_bytes(tpath("x.png"), "\x89PNG\r\n\x1a\n0000", 12);
    CHECK(load_fails_cleanly(tpath("x.png")));
    write_bytes(tpath("empty.exr"), "", 0);
    CHECK(load_fails_cleanly(tpath("empty.exr")));
    CHECK(load_fails_cleanly(tpath("does-not-exist.hdr")));
    CHECK(load_fails_cleanly(tmpdir));
    hfs_envmap_free(NULL);
}

/* ---- PFM ---------------------------------------------------------------------------- */

/* PF and Pf round trips (top row first, as hfs_pfm_write stores them), a NaN
 * named by its pixel, a mislabelled .pfm, every proper prefix refused. */
static void test_pfm(void)
{
    const int w = 7, h = 3;
    hfs_image img;
    hfs_error err = {{0}};
    CHECK(hfs_image_alloc(&img, w, h, &err) == 0);
    for (int k = 0; k < w * h * 3; ++k)
        img.rgb[k] = (float)(k * 0.25 + (k % 3) * 100.0);
    CHECK(hfs_pfm_write(tpath("sky.pfm"), &img, 0, &err) == 0);
    hfs_envmap m;
    CHECK(hfs_envmap_load(tpath("sky.pfm"), &m, &err) == 0);
    CHECK(m.width == w && m.height == h && m.rgb &&
          !memcmp(m.rgb, img.rgb, sizeof(float) * (size_t)(w * h * 3)));
    hfs_envmap_free(&m);
    check_prefixes(tpath("sky.pfm"), 1);

    /* Grey: R = G = B = the stored value. */
    float grey[7 * 3];
    for (int k = 0; k < w * h; ++k)
        grey[k] = (float)k * 1.5f;
    CHECK(hfs_pfm_write_grey(tpath("grey.pfm"), w, h, grey, &err) == 0);
    CHECK(hfs_envmap_load(tpath("grey.pfm"), &m, &err) == 0);
    int same = m.rgb != NULL;
    for (int k = 0; same && k < w * h; ++k)
        same = m.rgb[3 * k] == grey[k] && m.rgb[3 * k + 1] == grey[k] &&
               m.rgb[3 * k + 2] == grey[k];
    CHECK(same);
    hfs_envmap_free(&m);

    /* A NaN, written by hand (the writers refuse one): little-endian PF. */
    char head[32];
    const int hn = snprintf(head, sizeof head, "PF\n%d %d\n-1.0\n", w, h);
    unsigned char buf[32 + 7 * 3 * 3 * 4];
    memcpy(buf, head, (size_t)hn);
    for (int k = 0; k < w * h * 3; ++k) {
        const float v = k == (2 * w + 4) * 3 + 1 ? NAN : 1.0f;
        uint32_t u;
        memcpy(&u, &v, 4);
        for (int b = 0; b < 4; ++b)
            buf[hn + 4 * k + b] = (unsigned char)(u >> (8 * b));
    }
    write_bytes(tpath("nan.pfm"), buf, (size_t)hn + (size_t)(w * h * 3 * 4));
    CHECK(hfs_envmap_load(tpath("nan.pfm"), &m, &err) == HFS_E_FORMAT);
    CHECK(strstr(err.msg, "pixel (4, 2) is NaN") != NULL);
    CHECK(load_fails_cleanly(tpath("nan.pfm")));

    static const unsigned char hdr_sig[] = "#?RADIANCE\n";
    write_bytes(tpath("fake.pfm"), hdr_sig, sizeof hdr_sig - 1);
    CHECK(hfs_envmap_load(tpath("fake.pfm"), &m, &err) != 0);
    CHECK(strstr(err.msg, "named .pfm but the content is Radiance .hdr") != NULL);
    hfs_image_free(&img);
}

int main(void)
{
    if (make_tmpdir("io_envmap") != 0)
        return 1;
    test_hdr();
    test_exr_roundtrips();
    test_exr_refusals();
    test_pfm();
    rm_tmpdir();
    return finish_checks("test_io_envmap");
}
