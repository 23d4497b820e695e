/*
 * display.h — where the kiosk shows its frames, chosen by name.
 *
 * Backends (README.md and DISPLAY.md in this folder give their limits):
 *   "kms"       the board: DRM/KMS + GBM + EGL (EGL_PLATFORM_GBM_KHR) on the
 *               first card with a connected connector, in its preferred
 *               mode; presents with a page flip and waits for it (vsync).
 *   "x11"       a desktop window: Xlib + EGL (EGL_PLATFORM_X11_KHR), ES 3.0,
 *               swap interval 1.  Uses $DISPLAY.
 *   "headless"  no screen, no GL: keeps the last picture in memory and,
 *               when asked, writes each one as a numbered PNG.
 * A backend whose libraries were missing at configure time answers
 * "display NAME: not built (...)" with HFS_E_UNSUPPORTED.
 *
 * Pictures are sRGB RGBA8 (board/frame_image.h makes them from a render),
 * row 0 = TOP of the picture, alpha ignored (the screen is opaque).  A
 * display scales the picture to fit, keeping its aspect, centred on black:
 * nearest-neighbour when the scale is an integer (1:1 shows every byte
 * unchanged), bilinear otherwise (headless: always nearest).
 *
 * GL: x11 and kms make their own EGL display and ES 3.0 context and make it
 * current inside present (and handle_events, for x11 redraws); the renderer
 * makes its own context current at every frame, so the two coexist on one
 * thread.  After present the display's context is the current one: code
 * that makes GL calls of its own must make its context current again.
 *
 * Ownership: hfs_display_open returns an object freed by hfs_display_close
 * (NULL is a no-op).  Capture returns malloc'ed pixels the caller free()s.
 * Errors: 0 or a negative hfs_status, one line in err prefixed "display
 * NAME:"; nothing is printed.  Threads: one thread per display object.
 */
#ifndef HFS_DISPLAY_H
#define HFS_DISPLAY_H

#include <stdint.h>

#include "hfshade.h"

/* The largest picture side any display accepts (hfs_display_present); the
 * kiosk shrinks a larger field's picture to fit (frame_image.h). */
#define HFS_DISPLAY_MAX_SIDE 2048

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hfs_display hfs_display;

/* Zero / NULL means default for every field; a NULL opts pointer is all
 * defaults. */
typedef struct hfs_display_opts {
    int width, height;       /* x11: window size (default 640x480);
                                headless: canvas size, 0 = each picture's own;
                                kms: a mode of exactly this size, 0 = the
                                connector's preferred mode                    */
    const char *title;       /* x11: window title (default "hfshade")         */
    const char *device;      /* kms: "/dev/dri/cardN"; NULL = the first card
                                with a connected connector                     */
    const char *out_pattern; /* headless: printf pattern with one int, the
                                frame number from 0 ("frame-%04d.png"); NULL
                                = keep in memory only                          */
} hfs_display_opts;

/* Opens display name ("kms" | "x11" | "headless").  On failure *out is NULL
 * and the result is
 *   HFS_E_INVALID      unknown name (the message lists the known ones) or a
 *                      bad option;
 *   HFS_E_UNSUPPORTED  backend not built, or the device cannot do it (no
 *                      mode of the asked size);
 *   HFS_E_CONTEXT      the backend exists but no display could be opened
 *                      here ("display x11: cannot open X display ':0' ...",
 *                      "display kms: no DRM device with a connected
 *                      connector (/dev/dri: none)");
 *   HFS_E_NOMEM. */
int hfs_display_open(const char *name, const hfs_display_opts *o, hfs_display **out,
                     hfs_error *err);

/* Current size in pixels (x11: follows the window when it is resized;
 * headless without a size: the last picture's, 0x0 before the first). */
void hfs_display_size(const hfs_display *d, int *w, int *h);

/* The backend's name ("kms", "x11", "headless"); static string. */
const char *hfs_display_name(const hfs_display *d);

/* Shows a w x h sRGB RGBA8 picture (row 0 = top), scaled to fit (see the top
 * of this file).  x11 returns after eglSwapBuffers (swap interval 1); kms
 * after the page flip completed (vsync); headless after storing (and
 * writing) it.  rgba is only read during the call. */
int hfs_display_present(hfs_display *d, const uint8_t *rgba, int w, int h, hfs_error *err);

/* Embedding (issue 20): the EGLDisplay and EGLContext of a GL display
 * (x11, kms), for a renderer made to share with it
 * (hfs_renderer_desc.egl_display / egl_share_context); 1 then, 0 and NULLs
 * for a display without GL (headless).  Destroy such a renderer before
 * hfs_display_close (which terminates the EGL display under it). */
int hfs_display_gl_handles(const hfs_display *d, void **egl_display, void **egl_context);

/* Shows texture `texture` of that share group -- a w x h picture as
 * hfs_display_present takes (sRGB RGBA8, row 0 = top at t = 0), i.e.
 * hfs_renderer_render_texture's HFS_LIT_SRGB8 -- after a GPU-side wait on
 * fence (its GLsync; NULL: none), with no read-back and no upload; returns
 * as hfs_display_present does.  The texture must stay valid until the
 * next present (an x11 expose redraws it).  HFS_E_UNSUPPORTED without GL. */
int hfs_display_present_texture(hfs_display *d, unsigned texture, void *fence, int w, int h,
                                hfs_error *err);

/* A file descriptor to poll() for window-system events (x11: the X
 * connection), or -1 when there are none (kms, headless). */
int hfs_display_fd(const hfs_display *d);

/* Handles pending window-system events without blocking (x11: redraws
 * after an expose, follows resizes).  Returns 1 when the user asked to close
 * (x11: WM_DELETE_WINDOW), else 0.  Once 1, it stays 1. */
int hfs_display_handle_events(hfs_display *d);

/* What is on screen now, as RGBA8 (alpha 255), row 0 = top, in *rgba
 * (malloc'ed, the caller frees) of *w x *h.  x11: read back from the window
 * (XGetImage); headless: the last canvas; kms: HFS_E_UNSUPPORTED.  Before
 * the first present: HFS_E_INVALID. */
int hfs_display_capture(hfs_display *d, uint8_t **rgba, int *w, int *h, hfs_error *err);

/* Closes the window / gives the screen back (kms: restores the CRTC as it
 * was, drops DRM master).  NULL is a no-op. */
void hfs_display_close(hfs_display *d);

/* "kms, x11, headless", for help texts. */
const char *hfs_display_names(void);

#ifdef __cplusplus
}
#endif
#endif /* HFS_DISPLAY_H */
