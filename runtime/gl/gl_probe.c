/*
 * gl_probe.c — driver behaviour measured by drawing (gl_probe.h).
 */
#include "gl_probe.h"

#include "gl_shaders.h"
#include "gl_util.h"
#include "half.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Row 0 holds two adjacent halves, 1 and 1 + 2^-10, blended at a quarter:
 * 1 + 2^-12, which is no half (a rounding filter gives 1 or 1 + 2^-10).
 * Row 1 holds 0 and 1 blended at 0.3: no multiple of 2^-8 (a filter
 * keeping 8 bits of the fraction gives 77/256). */
static const char probe_frag[] =
    "precision highp float;\n"
    "uniform highp sampler2D u_tex;\n"
    "layout(location = 0) out highp uvec4 o_bits;\n"
    "void main()\n"
    "{\n"
    "    float a = texture(u_tex, vec2(0.375, 0.25)).x;\n"
    "    float b = texture(u_tex, vec2((0.5 + 0.3) / 2.0, 0.75)).x;\n"
    "    o_bits = uvec4(floatBitsToUint(a), floatBitsToUint(b), 0u, 0u);\n"
    "}\n";

/* HFS_GL_PAIR_FETCH: "1" 1, "0" 0, else -1 (probe). */
static int env_answer(void)
{
    const char *e = getenv("HFS_GL_PAIR_FETCH");
    return e && !strcmp(e, "1") ? 1 : e && !strcmp(e, "0") ? 0 : -1;
}

/* Whether the driver's blends were exact (0), inexact (1), or the probe
 * could not draw (-1). */
static int probe_blends(const hfs_gl *gl)
{
    GLuint prog = 0, tex = 0, vao = 0;
    hfs_gl_target bits = {0};
    hfs_error err = {""};
    int inexact = -1;
    if (hfs_gl_program_from_sources(gl, "fullscreen.vert", hfs_shader_source("fullscreen.vert"),
                                    "filter_probe.frag", probe_frag, NULL, &prog, &err))
        return -1;
    if (hfs_gl_target_create(gl, 1, 1, GL_RGBA32UI, &bits, &err)) {
        gl->DeleteProgram(prog);
        return -1;
    }
    const uint16_t halves[4] = {hfs_float_to_half(1.0f), hfs_float_to_half(1.0f + 0x1p-10f),
                                hfs_float_to_half(0.0f), hfs_float_to_half(1.0f)};
    gl->GenTextures(1, &tex);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_R16F, 2, 2, 0, GL_RED, GL_HALF_FLOAT, halves);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->GenVertexArrays(1, &vao);
    gl->BindVertexArray(vao);
    gl->UseProgram(prog);
    gl->Uniform1i(gl->GetUniformLocation(prog, "u_tex"), 0);
    gl->BindFramebuffer(GL_FRAMEBUFFER, bits.framebuffer);
    gl->Viewport(0, 0, 1, 1);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    uint32_t px[4] = {0, 0, 0, 0};
    gl->ReadPixels(0, 0, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT, px);
    float a, b;
    memcpy(&a, &px[0], sizeof a);
    memcpy(&b, &px[1], sizeof b);
    if (gl->GetError() == GL_NO_ERROR) /* NaN reads as inexact */
        inexact = !(fabs((a - 1.0) * 1024.0 - 0.25) <= 1.0 / 64 && fabs(b - 0.3) <= 0x1p-14);
    gl->BindVertexArray(0);
    gl->DeleteVertexArrays(1, &vao);
    gl->UseProgram(0);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->DeleteTextures(1, &tex);
    hfs_gl_target_destroy(gl, &bits);
    gl->DeleteProgram(prog);
    for (int i = 0; i < 8 && gl->GetError() != GL_NO_ERROR; ++i) {
    }
    return inexact;
}

int hfs_gl_probe_filter_inexact(const hfs_gl *gl)
{
    const int forced = env_answer();
    return forced >= 0 ? forced : probe_blends(gl) != 0;
}
