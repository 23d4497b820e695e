/*
 * display_backend.h — what a display backend implements (private to board/).
 * display.c picks the backend by name, checks arguments and adds the
 * "display NAME:" prefix to messages; backends only do their device's work.
 *
 * A backend object embeds struct hfs_display as its first member.  Tables
 * are const: no mutable globals.
 */
#ifndef HFS_DISPLAY_BACKEND_H
#define HFS_DISPLAY_BACKEND_H

#include "display.h"

struct hfs_display_backend {
    const char *name;
    /* opts is never NULL here.  Messages carry no prefix. */
    int (*open)(const hfs_display_opts *o, hfs_display **out, hfs_error *err);
    void (*close)(hfs_display *d);
    /* Arguments checked by display.c (rgba non-NULL, sizes >= 1). */
    int (*present)(hfs_display *d, const uint8_t *rgba, int w, int h, hfs_error *err);
    int (*fd)(const hfs_display *d);
    int (*handle_events)(hfs_display *d);
    int (*capture)(hfs_display *d, uint8_t **rgba, int *w, int *h, hfs_error *err);
    /* GL displays (NULL: none, headless): the EGL display and context a
     * renderer may share, and a texture of that share group shown as
     * present shows an upload (arguments checked by display.c). */
    void (*gl_handles)(const hfs_display *d, void **egl_display, void **egl_context);
    int (*present_texture)(hfs_display *d, unsigned texture, void *fence, int w, int h,
                           hfs_error *err);
};

struct hfs_display {
    const struct hfs_display_backend *backend;
    int width, height;  /* current size, kept up to date by the backend */
};

extern const struct hfs_display_backend hfs_display_backend_kms;
extern const struct hfs_display_backend hfs_display_backend_x11;
extern const struct hfs_display_backend hfs_display_backend_headless;

/* Where a src_w x src_h picture goes on a dst_w x dst_h screen: the largest
 * rectangle of the same aspect (rounded to whole pixels), centred.  *nearest
 * is 1 when the scale is a whole number (1:1 included), i.e. every source
 * pixel becomes an exact k x k block. */
typedef struct hfs_display_fit {
    int x, y, w, h;  /* x, y from the TOP-LEFT of the screen */
    int nearest;
} hfs_display_fit;

hfs_display_fit hfs_display_fit_rect(int src_w, int src_h, int dst_w, int dst_h);

#endif /* HFS_DISPLAY_BACKEND_H */
