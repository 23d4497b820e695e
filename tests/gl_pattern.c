/*
 * gl_pattern.c — see gl_pattern.h.
 */
#include "gl_pattern.h"
#include "gl_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double pattern_ref(int i, int j, int c, double sign)
{
    double x = i + 0.5, y = j + 0.5, v;
    switch (c) {
    case 0: v = (x - 32.0) * 0.25; break;
    case 1: v = y * y / 64.0; break;
    case 2: v = sin(x * 0.125) * cos(y * 0.0625); break;
    default: v = (double)PATTERN_GAIN * (x + 2.0 * y) / 1024.0; break;
    }
    return sign * v;
}

static double ulp16(double v)
{
    double a = fabs(v);
    if (a < 0x1p-14)
        return 0x1p-24;
    return ldexp(1.0, (int)floor(log2(a)) - 10);
}

double pattern_tolerance(int c, double ref)
{
    double tol = ulp16(ref) + 1e-6 * fabs(ref);
    if (c == 2)
        tol += 0x1p-12;
    return tol;
}

/* Portable float map, RGB, bottom row first (= GL row order). */
static void write_pfm(const char *path, const float *rgba, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "  cannot write %s\n", path);
        return;
    }
    fprintf(f, "PF\n%d %d\n-1.0\n", w, h);
    for (int p = 0; p < w * h; ++p)
        fwrite(&rgba[p * 4], sizeof *rgba, 3, f);
    fclose(f);
    fprintf(stderr, "  wrote %s\n", path);
}

static int compare(const float *got, double sign, const char *what, const char *tag)
{
    int bad = 0;
    for (int j = 0; j < PATTERN_SIZE; ++j)
        for (int i = 0; i < PATTERN_SIZE; ++i)
            for (int c = 0; c < 4; ++c) {
                double ref = pattern_ref(i, j, c, sign);
                double g = got[(j * PATTERN_SIZE + i) * 4 + c];
                double tol = pattern_tolerance(c, ref);
                int ok = fabs(g - ref) <= tol || (fabs(ref) < 0x1p-14 && g == 0.0);
                if (!ok && bad++ < 5)
                    fprintf(stderr, "  %s: pixel (%d,%d) channel %d: got %.9g, expected %.9g "
                            "+- %.3g\n", what, i, j, c, g, ref, tol);
            }
    if (bad) {
        fprintf(stderr, "  %s: %d of %d values outside tolerance\n", what, bad,
                PATTERN_SIZE * PATTERN_SIZE * 4);
        size_t n = (size_t)PATTERN_SIZE * PATTERN_SIZE * 4;
        float *expected = malloc(n * sizeof *expected), *diff = malloc(n * sizeof *diff);
        if (expected && diff) {
            for (size_t k = 0; k < n; ++k) {
                int p = (int)(k / 4), c = (int)(k % 4);
                expected[k] = (float)pattern_ref(p % PATTERN_SIZE, p / PATTERN_SIZE, c, sign);
                diff[k] = fabsf(got[k] - expected[k]);
            }
            char path[256];
            snprintf(path, sizeof path, "%s_actual.pfm", tag);
            write_pfm(path, got, PATTERN_SIZE, PATTERN_SIZE);
            snprintf(path, sizeof path, "%s_expected.pfm", tag);
            write_pfm(path, expected, PATTERN_SIZE, PATTERN_SIZE);
            snprintf(path, sizeof path, "%s_diff.pfm", tag);
            write_pfm(path, diff, PATTERN_SIZE, PATTERN_SIZE);
        }
        free(expected);
        free(diff);
    }
    return bad ? 1 : 0;
}

int pattern_check(const hfs_gl *gl, double sign, const char *tag)
{
    static const char *const negate[] = { "HFS_PATTERN_SIGN -1.0", NULL };
    hfs_error err = { "" };
    int failures = 0;
    GLuint program = 0, vao = 0;
    hfs_gl_target target;
    size_t n = (size_t)PATTERN_SIZE * PATTERN_SIZE * 4;
    float *pixels = malloc(n * sizeof *pixels), *other = malloc(n * sizeof *other);
    if (!pixels || !other) {
        fprintf(stderr, "  out of memory\n");
        free(pixels);
        free(other);
        return 1;
    }

    if (hfs_gl_program_create(gl, "fullscreen.vert", "pattern.frag", sign < 0 ? negate : NULL,
                              &program, &err)) {
        fprintf(stderr, "  %s\n", err.msg);
        failures++;
        goto out;
    }
    if (hfs_gl_target_create(gl, PATTERN_SIZE, PATTERN_SIZE, GL_RGBA16F, &target, &err)) {
        fprintf(stderr, "  %s\n", err.msg);
        failures++;
        goto out_program;
    }
    /* Core profile (osmesa) draws nothing without a bound vertex array. */
    gl->GenVertexArrays(1, &vao);
    gl->BindVertexArray(vao);
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    const GLenum attachment = GL_COLOR_ATTACHMENT0;
    gl->DrawBuffers(1, &attachment);
    gl->Viewport(0, 0, PATTERN_SIZE, PATTERN_SIZE);
    const GLfloat clear[4] = { 1e4f, 1e4f, 1e4f, 1e4f }; /* loud if not overdrawn */
    gl->ClearBufferfv(GL_COLOR, 0, clear);
    gl->UseProgram(program);
    gl->Uniform1f(gl->GetUniformLocation(program, "u_gain"), PATTERN_GAIN);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->UseProgram(0);
    if (hfs_gl_check(gl, "draw pattern", &err)) {
        fprintf(stderr, "  %s\n", err.msg);
        failures++;
        goto out_target;
    }

    hfs_gl_read_path used = HFS_GL_READ_AUTO;
    if (hfs_gl_read_rgba(gl, target.framebuffer, 0, 0, PATTERN_SIZE, PATTERN_SIZE,
                         HFS_GL_READ_AUTO, pixels, &used, &err)) {
        fprintf(stderr, "  %s\n", err.msg);
        failures++;
        goto out_target;
    }
    fprintf(stderr, "  sign %+.0f: readback auto chose %s\n", sign,
            used == HFS_GL_READ_HALF ? "RGBA/HALF_FLOAT" : "RGBA/FLOAT");
    failures += compare(pixels, sign, "auto readback", tag);

    /* The other paths must give the same bits where the GL accepts them. */
    static const struct { hfs_gl_read_path path; const char *name; } forced[] = {
        { HFS_GL_READ_FLOAT, "RGBA/FLOAT" }, { HFS_GL_READ_HALF, "RGBA/HALF_FLOAT" },
    };
    for (size_t k = 0; k < sizeof forced / sizeof forced[0]; ++k) {
        if (hfs_gl_read_rgba(gl, target.framebuffer, 0, 0, PATTERN_SIZE, PATTERN_SIZE,
                             forced[k].path, other, NULL, &err)) {
            fprintf(stderr, "  note: forced %s not accepted here: %s\n", forced[k].name,
                    err.msg);
            continue;
        }
        if (memcmp(other, pixels, n * sizeof *pixels) != 0) {
            fprintf(stderr, "  forced %s readback differs from auto\n", forced[k].name);
            failures++;
        }
    }

out_target:
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->BindVertexArray(0);
    if (vao)
        gl->DeleteVertexArrays(1, &vao);
    hfs_gl_target_destroy(gl, &target);
out_program:
    gl->DeleteProgram(program);
out:
    if (hfs_gl_check(gl, "pattern teardown", &err)) {
        fprintf(stderr, "  %s\n", err.msg);
        failures++;
    }
    free(pixels);
    free(other);
    return failures;
}
