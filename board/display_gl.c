/*
 * display_gl.c — EGL display/surface/context and the picture blit shared by
 * the "x11" and "kms" displays (display_gl.h).
 *
 * Why a shader blit and not glBlitFramebuffer: the picture must be flipped
 * (row 0 on top), scaled with a chosen filter and letterboxed on every ES
 * 3.0 device; one textured full-screen triangle does all of it, and at 1:1
 * with NEAREST every window pixel samples exactly its texel centre, so the
 * bytes arrive unchanged (checked under Xvfb by test_display_x11).
 *
 * Invariants: every object this file creates is recorded in the struct as
 * soon as it exists, so hfs_dgl_close can undo any partial start.
 */
#include "egl_util.h"
#include "display_gl.h"
#include "display_backend.h"
#include "gl_util.h"

#include <string.h>

int hfs_dgl_egl_fail(hfs_error *err, int code, const char *what)
{
    return hfs_fail(err, code, "%s failed (%s)", what, hfs_egl_error_name(eglGetError()));
}

int hfs_dgl_open(hfs_display_gl *g, EGLenum platform, void *native,
                 const char *const *platform_exts, hfs_error *err)
{
    memset(g, 0, sizeof *g);
    g->display = EGL_NO_DISPLAY;
    g->context = EGL_NO_CONTEXT;
    g->surface = EGL_NO_SURFACE;

    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    int have_platform = 0;
    for (const char *const *e = platform_exts; *e; ++e)
        have_platform |= hfs_egl_has_word(client, *e);
    if (!client || !hfs_egl_has_word(client, "EGL_EXT_platform_base") || !have_platform)
        return hfs_fail(err, HFS_E_CONTEXT, "%s not offered by this libEGL", platform_exts[0]);
    /* EGL 1.5's eglGetPlatformDisplay takes EGLAttrib; the EXT entry points
     * exist wherever the client extension is listed, so use those. */
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    g->create_window_surface = (PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC)eglGetProcAddress(
        "eglCreatePlatformWindowSurfaceEXT");
    if (!get_display || !g->create_window_surface)
        return hfs_fail(err, HFS_E_CONTEXT, "EGL_EXT_platform_base entry points not found");
    EGLDisplay dpy = get_display(platform, native, NULL);
    if (dpy == EGL_NO_DISPLAY)
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglGetPlatformDisplayEXT");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(dpy, &major, &minor))
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglInitialize");
    g->display = dpy;
    const char *exts = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!(major > 1 || minor >= 5) && !hfs_egl_has_word(exts, "EGL_KHR_create_context"))
        return hfs_fail(err, HFS_E_CONTEXT, "EGL %d.%d without EGL_KHR_create_context cannot "
                        "make an ES 3 context", major, minor);
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglBindAPI(EGL_OPENGL_ES_API)");
    return HFS_OK;
}

int hfs_dgl_choose_config(hfs_display_gl *g, EGLint native_visual, EGLint *visual_out,
                          hfs_error *err)
{
    const EGLint attribs[] = {
        EGL_SURFACE_TYPE, EGL_WINDOW_BIT,
        EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
        EGL_NONE
    };
    EGLConfig configs[256];
    EGLint n = 0;
    if (!eglChooseConfig(g->display, attribs, configs, 256, &n))
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglChooseConfig");
    /* EGL sorts deeper colour buffers first, i.e. RGBA before RGB; an alpha
     * channel would give an X window of depth 32 for nothing. */
    int best = -1, best_score = -1;
    for (EGLint i = 0; i < n; ++i) {
        EGLint r = 0, gr = 0, b = 0, a = 0, vis = 0;
        eglGetConfigAttrib(g->display, configs[i], EGL_RED_SIZE, &r);
        eglGetConfigAttrib(g->display, configs[i], EGL_GREEN_SIZE, &gr);
        eglGetConfigAttrib(g->display, configs[i], EGL_BLUE_SIZE, &b);
        eglGetConfigAttrib(g->display, configs[i], EGL_ALPHA_SIZE, &a);
        eglGetConfigAttrib(g->display, configs[i], EGL_NATIVE_VISUAL_ID, &vis);
        if (r != 8 || gr != 8 || b != 8)
            continue; /* 10-bit configs would still be exact, but keep it simple */
        if (native_visual >= 0 && vis != native_visual)
            continue;
        int score = a == 0 ? 2 : 1;
        if (score > best_score) {
            best = (int)i;
            best_score = score;
        }
    }
    if (best < 0)
        return hfs_fail(err, HFS_E_CONTEXT, "no EGL window config with 8-bit RGB and ES 3%s",
                        native_visual >= 0 ? " for the scan-out format" : "");
    g->config = configs[best];
    if (visual_out) {
        EGLint vis = 0;
        eglGetConfigAttrib(g->display, g->config, EGL_NATIVE_VISUAL_ID, &vis);
        *visual_out = vis;
    }
    return HFS_OK;
}

static void *egl_loader(void *user, const char *name)
{
    (void)user;
    /* POSIX lets function pointers round-trip through void * (dlsym). */
    return (void *)eglGetProcAddress(name);
}

int hfs_dgl_start(hfs_display_gl *g, void *native_window, hfs_error *err)
{
    int rc;
    g->surface = g->create_window_surface(g->display, g->config, native_window, NULL);
    if (g->surface == EGL_NO_SURFACE)
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglCreatePlatformWindowSurfaceEXT");
    const EGLint context_attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION, 3,
        EGL_CONTEXT_MINOR_VERSION, 0,
        EGL_NONE
    };
    g->context = eglCreateContext(g->display, g->config, EGL_NO_CONTEXT, context_attribs);
    if (g->context == EGL_NO_CONTEXT)
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglCreateContext(OpenGL ES 3.0)");
    if ((rc = hfs_dgl_make_current(g, err)))
        return rc;
    /* Swap interval 1: one picture per refresh, no tearing (kms waits for
     * its page flip instead; Xvfb has no vblank and ignores it). */
    eglSwapInterval(g->display, 1);
    if ((rc = hfs_gl_load(&g->gl, egl_loader, NULL, err)))
        return rc;
    if ((rc = hfs_gl_program_create(&g->gl, "fullscreen.vert", "display_blit.frag", NULL,
                                    &g->program, err)))
        return rc;
    const hfs_gl *gl = &g->gl;
    gl->UseProgram(g->program);
    gl->Uniform1i(gl->GetUniformLocation(g->program, "u_image"), 0);
    gl->GenVertexArrays(1, &g->vao); /* ES allows VAO 0, desktop core does not */
    gl->GenTextures(1, &g->texture);
    gl->BindTexture(GL_TEXTURE_2D, g->texture);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return hfs_gl_check(gl, "display set-up", err);
}

int hfs_dgl_make_current(hfs_display_gl *g, hfs_error *err)
{
    /* The bound API is per thread; the application may have changed it. */
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglBindAPI(EGL_OPENGL_ES_API)");
    if (!eglMakeCurrent(g->display, g->surface, g->surface, g->context))
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglMakeCurrent");
    return HFS_OK;
}

int hfs_dgl_draw(hfs_display_gl *g, const uint8_t *rgba, int w, int h, int dst_w, int dst_h,
                 hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    gl->ActiveTexture(GL_TEXTURE0);
    if (rgba) {
        gl->BindTexture(GL_TEXTURE_2D, g->texture);
        gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4); /* RGBA8 rows: always a multiple of 4 */
        if (w != g->own_w || h != g->own_h) {
            gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
            g->own_w = w;
            g->own_h = h;
        } else {
            gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        }
        hfs_dgl_show_texture(g, g->texture, NULL, w, h);
    }
    if (g->tex_w < 1)
        return HFS_OK; /* nothing shown yet: nothing to redraw */
    if (g->fence) { /* the renderer's frame done before we sample it (on the GPU) */
        gl->WaitSync((GLsync)g->fence, 0, GL_TIMEOUT_IGNORED);
        g->fence = NULL;
    }
    gl->BindTexture(GL_TEXTURE_2D, g->shown);

    hfs_display_fit f = hfs_display_fit_rect(g->tex_w, g->tex_h, dst_w, dst_h);
    GLint filter = f.nearest ? GL_NEAREST : GL_LINEAR;
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);

    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->Viewport(0, 0, dst_w, dst_h);
    gl->ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl->Clear(GL_COLOR_BUFFER_BIT);
    /* GL's window origin is the bottom-left corner; the fit's is top-left. */
    gl->Viewport(f.x, dst_h - f.y - f.h, f.w, f.h);
    gl->UseProgram(g->program);
    gl->BindVertexArray(g->vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    return hfs_gl_check(gl, "display draw", err);
}

void hfs_dgl_show_texture(hfs_display_gl *g, unsigned tex, void *fence, int w, int h)
{
    g->shown = tex;
    g->fence = fence;
    g->tex_w = w;
    g->tex_h = h;
}

int hfs_dgl_swap(hfs_display_gl *g, hfs_error *err)
{
    if (!eglSwapBuffers(g->display, g->surface))
        return hfs_dgl_egl_fail(err, HFS_E_CONTEXT, "eglSwapBuffers");
    return HFS_OK;
}

void hfs_dgl_close(hfs_display_gl *g)
{
    if (g->display == EGL_NO_DISPLAY)
        return;
    if (g->context != EGL_NO_CONTEXT) {
        /* GL objects go with the context, but delete them explicitly where
         * we can: a shared-context set-up would otherwise keep them. */
        if (g->gl.DeleteProgram && eglMakeCurrent(g->display, g->surface, g->surface,
                                                  g->context)) {
            if (g->program)
                g->gl.DeleteProgram(g->program);
            if (g->texture)
                g->gl.DeleteTextures(1, &g->texture);
            if (g->vao)
                g->gl.DeleteVertexArrays(1, &g->vao);
        }
        if (eglGetCurrentContext() == g->context)
            eglMakeCurrent(g->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(g->display, g->context);
    }
    if (g->surface != EGL_NO_SURFACE)
        eglDestroySurface(g->display, g->surface);
    eglTerminate(g->display);
    memset(g, 0, sizeof *g);
    g->display = EGL_NO_DISPLAY;
}
