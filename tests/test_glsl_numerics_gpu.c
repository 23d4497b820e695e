/*
 * test_glsl_numerics_gpu.c — the shader library's numerics (gles_pairs.frag,
 * gles_lib.frag) EXECUTED on the GL driver, where a real GPU's compiler,
 * fast transcendentals and texture filter part ways with a CPU's (llvmpipe
 * passes either way; an NVIDIA H200 did not before them):
 *
 *   halves   hfs_half_nearest(v) against runtime/gl/half.h's float -> half
 *            (round to nearest even) bit for bit, and hfs_split(v): hi a
 *            half, hi + lo == v.  Written as unpackHalf2x16(packHalf2x16(v))
 *            these returned v itself on the H200 (the pair folded away), so
 *            every stored hi+lo pair kept lo = 0;
 *
 *   sine     hfs_sin_acc(a) for a from 1e-8 to pi/2: relative error.  A GPU
 *            may compute sin() with an ABSOLUTE error near 2^-21 (NVIDIA's
 *            hardware sine, measured on an H200: see BENCHMARKS.md "On a
 *            real GPU"), which at a 1e-8 rad sun is no digit at all;
 *   caps     hfs_cap_irradiance(cos_beta, alpha) (key lights) for the same
 *            half-angles, caps above, straddling and below the tangent
 *            plane: the error to hfs_cap_irradiance (lights.c) over the
 *            light's irradiance at normal incidence, pi sin^2(alpha);
 *   filter   runtime/gl/gl_probe.h's answer against this test's own sweep
 *            of LINEAR's position and half rounding (printed);
 *   blend    hfs_pair_tex4 and hfs_pair_tex4_layer under HFS_PAIR_FETCH
 *            against the exact bilinear blend of the pairs' sums, in 2-D,
 *            in an array layer and beyond the edges.
 *
 * The driver's own sin() is printed beside them (information: it is what a
 * shader would get without hfs_sin_acc: on the H200 sin(1e-8) had no
 * correct digit, sin(1e-5) 0.75% off).  Exact readback as in
 * test_sh_glsl_gpu.c: floatBitsToUint into an RGBA32UI target.  Bounds
 * about 4x the worst measured on llvmpipe and the H200; the halves exact.
 *
 * Exit 77 (skip) only when no GL context can be made here.
 */
#include "gl_bits.h"
#include "gl_probe.h"
#include "half.h"
#include "hfshade.h"
#include "lights.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define NP 64 /* (cos_beta, alpha) pairs per draw: one pixel each */
#define PW 5  /* the pair textures of check_pair_blend: PW x PH texels */
#define PH 3

#define TEST_RNG_SEED 0x2545f4914f6cdd1dull
#include "test_rng.h"

static const char *frag_main =
    "uniform vec2 u_in[64];\n"
    "layout(location = 0) out highp uvec4 o_bits;\n"
    "float hfs_cap_irradiance(float cos_beta, float alpha);\n"
    "float hfs_sin_acc(float x);\n"
    "float hfs_half_nearest(float v);\n"
    "vec2 hfs_split(float v);\n"
    "vec4 hfs_pair_tex4(highp sampler2D t, vec2 uv);\n"
    "uniform int u_mode;\n"
    "uniform highp sampler2D u_tex;\n"
    "uniform highp sampler2D u_pairs;\n"
    "uniform highp sampler2DArray u_pairs_arr;\n"
    "vec4 hfs_pair_tex4_layer(highp sampler2DArray t, vec3 uvl);\n"
    "void main()\n"
    "{\n"
    "    vec2 a = u_in[int(gl_FragCoord.x)];\n"
    "    if (u_mode == 0)\n"
    "        o_bits = floatBitsToUint(vec4(hfs_cap_irradiance(a.x, a.y), hfs_sin_acc(a.y),\n"
    "                                      sin(a.y), 0.0));\n"
    "    else if (u_mode == 1)\n"
    "        o_bits = floatBitsToUint(vec4(hfs_half_nearest(a.x), hfs_split(a.x), 0.0));\n"
    "    else if (u_mode == 3)\n"
    "        o_bits = floatBitsToUint(vec4(hfs_pair_tex4(u_pairs, a).xz,\n"
    "                                      hfs_pair_tex4_layer(u_pairs_arr, vec3(a, 1.0)).xz));\n"
    "    else\n"
    "        o_bits = floatBitsToUint(vec4(texture(u_tex, vec2((0.5 + a.x) / 2.0, 0.25)).x,\n"
    "                                      texture(u_tex, vec2((0.5 + a.x) / 2.0, 0.75)).x,\n"
    "                                      hfs_pair_tex4(u_tex, vec2((0.5 + a.x) / 2.0, 0.75)).x,\n"
    "                                      0.0));\n"
    "}\n";

typedef struct gpu_prog {
    gl_bits b;                     /* the program and its NP x 1 target */
    GLuint ramp, pairs, pairs_arr; /* check_filter's; check_pair_blend's */
    uint16_t pair_data[2][PW * PH * 4]; /* the 2-D texture; the array's layer 1 */
} gpu_prog;

static GLuint linear_texture(const hfs_gl *gl, GLenum target)
{
    GLuint t;
    gl->GenTextures(1, &t);
    gl->BindTexture(target, t);
    gl->TexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

/* check_filter's 2x2 R16F texture: row 0 (0, 1), where texture() at x = f
 * returns the driver's weight for f; row 1 two adjacent halves (1,
 * 1 + 2^-10), where it shows whether the result is rounded to a half.
 * check_pair_blend's: two pairs a texel (hi a half in [-1, 1], lo one below
 * its ulp) in an RGBA16F texture and in layer 1 of a two-layer array. */
static void make_textures(gpu_prog *g, const hfs_gl *gl)
{
    const uint16_t ramp[4] = {hfs_float_to_half(0.0f), hfs_float_to_half(1.0f),
                              hfs_float_to_half(1.0f), hfs_float_to_half(1.0f + 0x1p-10f)};
    g->ramp = linear_texture(gl, GL_TEXTURE_2D);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_R16F, 2, 2, 0, GL_RED, GL_HALF_FLOAT, ramp);
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < PW * PH * 4; i += 2) {
            g->pair_data[k][i] = hfs_float_to_half((float)(2.0 * urand() - 1.0));
            g->pair_data[k][i + 1] = hfs_float_to_half((float)((2.0 * urand() - 1.0) * 0x1p-12));
        }
    g->pairs = linear_texture(gl, GL_TEXTURE_2D);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, PW, PH, 0, GL_RGBA, GL_HALF_FLOAT, g->pair_data[0]);
    static const uint16_t zero[PW * PH * 4];
    g->pairs_arr = linear_texture(gl, GL_TEXTURE_2D_ARRAY);
    gl->TexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA16F, PW, PH, 2, 0, GL_RGBA, GL_HALF_FLOAT, NULL);
    gl->TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, PW, PH, 1, GL_RGBA, GL_HALF_FLOAT, zero);
    gl->TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 1, PW, PH, 1, GL_RGBA, GL_HALF_FLOAT,
                      g->pair_data[1]);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    gl->BindTexture(GL_TEXTURE_2D, 0);
}

static int gpu_init(gpu_prog *g, const hfs_gl *gl, hfs_error *err)
{
    memset(g, 0, sizeof *g);
    const char *pairs = hfs_shader_source("gles_pairs.frag");
    const char *lib = hfs_shader_source("gles_lib.frag");
    if (!pairs || !lib)
        return hfs_fail(err, HFS_E_INVALID, "gles_pairs.frag or gles_lib.frag not embedded");
    const size_t size = strlen(pairs) + strlen(lib) + strlen(frag_main) + 16;
    char *src = malloc(size);
    if (!src)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    snprintf(src, size, "%s\n%s\n%s", pairs, lib, frag_main);
    /* the pairs blended as on a driver whose filter is inexact (gl_probe.h) */
    const char *defs[] = {"HFS_PAIR_FETCH 1", NULL};
    const int rc = gl_bits_init(&g->b, gl, "numerics_test.frag", src, defs, NP, 1, err);
    free(src);
    if (rc)
        return rc;
    make_textures(g, gl);
    return hfs_gl_check(gl, "numerics test setup", err);
}

static void gpu_free(gpu_prog *g)
{
    const hfs_gl *gl = g->b.gl;
    if (!gl)
        return;
    const GLuint t[3] = {g->ramp, g->pairs, g->pairs_arr};
    gl->DeleteTextures(3, t);
    gl_bits_free(&g->b);
}

/* mode 0: out[p] = (cap, hfs_sin_acc, sin, 0) of pair p (n <= NP);
 * mode 1: (hfs_half_nearest, hfs_split's hi and lo, 0) of in[p][0];
 * mode 2: LINEAR and hfs_pair_tex4 on the probe textures at in[p][0];
 * mode 3: hfs_pair_tex4 and hfs_pair_tex4_layer's two pairs at uv in[p]. */
static int gpu_run(gpu_prog *g, int mode, int n, const float in[][2], float out[][4],
                   hfs_error *err)
{
    const hfs_gl *gl = g->b.gl;
    const GLuint prog = g->b.program;
    float u[NP * 2] = {0};
    memcpy(u, in, (size_t)n * 2 * sizeof(float));
    gl->UseProgram(prog);
    gl->Uniform2fv(gl->GetUniformLocation(prog, "u_in"), NP, u);
    gl->Uniform1i(gl->GetUniformLocation(prog, "u_mode"), mode);
    gl->Uniform1i(gl->GetUniformLocation(prog, "u_tex"), 0);
    gl->Uniform1i(gl->GetUniformLocation(prog, "u_pairs"), 1);
    gl->Uniform1i(gl->GetUniformLocation(prog, "u_pairs_arr"), 2);
    gl->ActiveTexture(GL_TEXTURE1);
    gl->BindTexture(GL_TEXTURE_2D, g->pairs);
    gl->ActiveTexture(GL_TEXTURE2);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, g->pairs_arr);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, g->ramp);
    uint32_t bits[NP * 4];
    const int rc = gl_bits_draw(&g->b, bits, err);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    memcpy(out, bits, (size_t)n * 4 * sizeof(float));
    return rc;
}

static double rel_err(double got, double want)
{
    return fabs(got - want) / fabs(want);
}

static void check_lights(gpu_prog *g)
{
    static const double alphas[] = {1e-8, 3e-7, 1e-5, 1e-4, 1e-3, 0.01, 0.05,
                                    0.2,  0.45, 0.55, 1.0,  1.5};
    enum { NA = sizeof alphas / sizeof alphas[0], NB = 5 };
    float in[NA * NB][2], out[NA * NB][4];
    for (int a = 0; a < NA; ++a) {
        const double s = sin(alphas[a]);
        /* above the plane, at its edge, straddling by half a radius, just
         * below and wholly below */
        const double cb[NB] = {0.8, 1.0001 * s, 0.5 * s, -0.5 * s, -0.9};
        for (int b = 0; b < NB; ++b)
            in[a * NB + b][0] = (float)cb[b], in[a * NB + b][1] = (float)alphas[a];
    }
    hfs_error err = {""};
    if (gpu_run(g, 0, NA * NB, (const float(*)[2])in, out, &err)) {
        CHECK(0, "%s", err.msg);
        return;
    }
    double worst_sin = 0.0, worst_raw = 0.0, worst_cap = 0.0;
    for (int a = 0; a < NA; ++a) {
        /* the double references of the float inputs the shader saw */
        const double al = in[a * NB][1], s = sin(al);
        const double es = rel_err(out[a * NB][1], s), er = rel_err(out[a * NB][2], s);
        worst_sin = fmax(worst_sin, es), worst_raw = fmax(worst_raw, er);
        printf("alpha %-7.1e  sin: hfs_sin_acc %.2e  driver sin %.2e  caps:", al, es, er);
        for (int b = 0; b < NB; ++b) {
            const double want = hfs_cap_irradiance(in[a * NB + b][0], al), got = out[a * NB + b][0];
            /* the error over the light's irradiance at normal incidence
             * (pi s^2): a straddling cap's value runs down to 0 at the
             * plane, where float's own cancellation is relative to that */
            const double e = fabs(got - want) / (3.14159265358979323846 * s * s);
            worst_cap = fmax(worst_cap, e);
            printf(" %.1e", e);
        }
        printf("\n");
    }
    /* measured: sine 6.6e-8 (llvmpipe), 1.0e-7 (H200); caps 2.5e-5, 1.8e-5 */
    printf("worst relative error: hfs_sin_acc %.2e (bound 4e-7), driver sin %.2e (not bounded), "
           "caps %.2e (bound 1e-4)\n", worst_sin, worst_raw, worst_cap);
    CHECK(worst_sin <= 4e-7, "hfs_sin_acc: relative error %.3g > 4e-7", worst_sin);
    CHECK(worst_cap <= 1e-4, "hfs_cap_irradiance: error %.3g of pi sin^2 > 1e-4", worst_cap);
}

/* hfs_half_nearest and hfs_split over halves' whole range: powers of two
 * and their neighbours, ties, the subnormal halves, 65504 and random
 * floats of every exponent from 2^-30 to 2^15.9, both signs. */
static void check_halves(gpu_prog *g)
{
    enum { N = 64 * 40 };
    static float v[N];
    int n = 0;
    for (int e = -26; e <= 15 && n + 6 <= N; ++e) {
        const float p = ldexpf(1.0f, e);
        v[n++] = p, v[n++] = nextafterf(p, 0.0f), v[n++] = nextafterf(p, 1e30f);
        v[n++] = p * (1.0f + ldexpf(1.0f, -11)); /* a tie between two halves */
        v[n++] = p * (1.0f + 3.0f * ldexpf(1.0f, -11)); /* a tie, the other parity */
        v[n++] = -p * 1.3f;
    }
    v[n++] = 65504.0f, v[n++] = 65519.0f, v[n++] = -65504.0f, v[n++] = 0.0f;
    while (n < N) {
        const double e = -30.0 + 45.9 * urand(); /* below 2^15.9: no half-less floats */
        v[n++] = (float)((urand() < 0.5 ? -1.0 : 1.0) * exp2(e));
    }
    long bad_near = 0, bad_split = 0;
    hfs_error err = {""};
    for (int b = 0; b < N; b += NP) {
        float in[NP][2], out[NP][4];
        for (int p = 0; p < NP; ++p)
            in[p][0] = v[b + p], in[p][1] = 0.0f;
        if (gpu_run(g, 1, NP, (const float(*)[2])in, out, &err)) {
            CHECK(0, "%s", err.msg);
            return;
        }
        for (int p = 0; p < NP; ++p) {
            const float x = in[p][0], want = hfs_half_to_float(hfs_float_to_half(x));
            const float hi = out[p][1], lo = out[p][2];
            if (memcmp(&out[p][0], &want, sizeof want) && bad_near++ < 5)
                fprintf(stderr, "hfs_half_nearest(%.9g) = %.9g, want %.9g\n", x, out[p][0], want);
            const int hi_half = hfs_half_to_float(hfs_float_to_half(hi)) == hi;
            if ((!hi_half || hi + lo != x) && bad_split++ < 5)
                fprintf(stderr, "hfs_split(%.9g) = (%.9g, %.9g)\n", x, hi, lo);
        }
    }
    printf("halves: %d values, hfs_half_nearest wrong on %ld, hfs_split wrong on %ld\n", N,
           bad_near, bad_split);
    CHECK(bad_near == 0, "hfs_half_nearest: %ld of %d values not the nearest half", bad_near, N);
    CHECK(bad_split == 0, "hfs_split: %ld of %d values not a half + the rest", bad_split, N);
}

/* Information, not a check (the precision of filtering is the driver's):
 * how finely LINEAR resolves a position between two texels, and whether it
 * rounds a 16F blend to a half (runtime/gl/gl_probe.h: the H200 kept 8 bits
 * of the position and rounded).  Checked: hfs_pair_tex4 under
 * HFS_PAIR_FETCH, the renderer's answer to such a driver, blends in float
 * at the exact position. */
static void check_filter(gpu_prog *g)
{
    hfs_error err = {""};
    double worst = 0.0, worst_adj = 0.0, worst_pair = 0.0;
    for (int b = 0; b < 1024; b += NP) {
        float in[NP][2], out[NP][4];
        for (int p = 0; p < NP; ++p)
            in[p][0] = (float)(b + p) / 1024.0f + 0.000377f, in[p][1] = 0.0f;
        if (gpu_run(g, 2, NP, (const float(*)[2])in, out, &err)) {
            CHECK(0, "%s", err.msg);
            return;
        }
        for (int p = 0; p < NP; ++p) {
            worst = fmax(worst, fabs(out[p][0] - in[p][0]));
            worst_adj = fmax(worst_adj, fabs((out[p][1] - 1.0) * 1024.0 - in[p][0]));
            worst_pair = fmax(worst_pair, fabs((out[p][2] - 1.0) * 1024.0 - in[p][0]));
        }
    }
    printf("filter: LINEAR between two texels is off the position by up to %.2e of a texel "
           "(2^%.1f); between adjacent halves by %.2e of their step (0.5: the result is "
           "rounded to a half)\n", worst, worst > 0.0 ? log2(worst) : -99.0, worst_adj);
    /* hfs_pair_tex4 under HFS_PAIR_FETCH blends in float: the position
     * to float's precision, 2^-13 of the step here (1 + x 2^-10 in a
     * float keeps 13 bits of x) */
    /* gl_probe.h's answer, from its own two samples, against this sweep's */
    const int inexact = worst > 0x1p-14 || worst_adj > 1.0 / 64, probe = hfs_gl_probe_filter_inexact(g->b.gl);
    const char *env = getenv("HFS_GL_PAIR_FETCH");
    printf("gl_probe: filter %s (this sweep: %s)%s\n", probe ? "inexact" : "exact",
           inexact ? "inexact" : "exact", env ? " (HFS_GL_PAIR_FETCH set: not compared)" : "");
    CHECK(env || probe == inexact, "hfs_gl_probe_filter_inexact says %d, the sweep %d", probe,
          inexact);
    printf("hfs_pair_tex4 (HFS_PAIR_FETCH): off by %.2e of the step (bound 5e-5)\n", worst_pair);
    CHECK(worst_pair <= 5e-5, "hfs_pair_tex4: off by %.3g of the step", worst_pair);
}

/* The pair sums of data (PW x PH, two pairs a texel) blended at uv as
 * texture() does with CLAMP_TO_EDGE, in double; pair c of the texel. */
static double pair_bilinear(const uint16_t *data, double u, double v, int c)
{
    const double px = u * PW - 0.5, py = v * PH - 0.5, fx = px - floor(px), fy = py - floor(py);
    double s[2][2];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            int x = (int)floor(px) + i, y = (int)floor(py) + j;
            x = x < 0 ? 0 : x > PW - 1 ? PW - 1 : x;
            y = y < 0 ? 0 : y > PH - 1 ? PH - 1 : y;
            const uint16_t *t = data + 4 * (y * PW + x) + 2 * c;
            s[j][i] = (double)hfs_half_to_float(t[0]) + hfs_half_to_float(t[1]);
        }
    const double top = s[0][0] + fx * (s[0][1] - s[0][0]), bot = s[1][0] + fx * (s[1][1] - s[1][0]);
    return top + fy * (bot - top);
}

/* hfs_pair_tex4 and hfs_pair_tex4_layer under HFS_PAIR_FETCH against the
 * exact blend of the pairs' sums: random positions over the texture and
 * beyond its edges (clamped), both pairs of a texel, the array's layer. */
static void check_pair_blend(gpu_prog *g)
{
    hfs_error err = {""};
    double worst = 0.0;
    for (int b = 0; b < 4; ++b) {
        float in[NP][2], out[NP][4];
        for (int p = 0; p < NP; ++p)
            in[p][0] = (float)uni(-0.2, 1.2), in[p][1] = (float)uni(-0.2, 1.2);
        if (gpu_run(g, 3, NP, (const float(*)[2])in, out, &err)) {
            CHECK(0, "%s", err.msg);
            return;
        }
        for (int p = 0; p < NP; ++p)
            for (int k = 0; k < 4; ++k) {
                const double want = pair_bilinear(g->pair_data[k / 2], in[p][0], in[p][1], k % 2);
                worst = fmax(worst, fabs(out[p][k] - want));
            }
    }
    /* measured 3.0e-7 (llvmpipe): float's rounding of uv and the blend */
    printf("pair blend (HFS_PAIR_FETCH): off the exact blend by %.2e (bound 1e-6)\n", worst);
    CHECK(worst <= 1e-6, "hfs_pair_tex4(_layer): off the exact blend by %.3g", worst);
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    hfs_gl gl;
    hfs_gl_context *ctx = gl_bits_context(argc > 1 ? argv[1] : "surfaceless", &gl);
    gpu_prog g;
    hfs_error err = {""};
    const int rc = gpu_init(&g, &gl, &err);
    CHECK(rc == 0, "numerics program: %s", err.msg);
    if (rc == 0) {
        check_lights(&g);
        check_halves(&g);
        check_filter(&g);
        check_pair_blend(&g);
    }
    gpu_free(&g);
    hfs_gl_context_destroy(ctx);
    if (failures) {
        printf("FAIL: %d check(s) failed\n", failures);
        return 1;
    }
    printf("PASS\n");
    return 0;
}
