/*
 * kiosk_harness.h — running hfshade-kiosk from a test: spawn it with its
 * stderr in a file, wait for what it writes, signal it, read its --stats
 * file and frames, and render the same scene directly with the library for
 * a byte-exact comparison.  Used by test_kiosk.c.
 */
#ifndef HFS_KIOSK_HARNESS_H
#define HFS_KIOSK_HARNESS_H

#include <stdint.h>
#include <sys/types.h>

#include "hfs_io.h"
#include "hfshade.h"

/* Creates a private directory (under /tmp) and returns its path, or NULL. */
const char *kh_tmpdir(const char *tag);
/* "tmpdir/name" in one of eight rotating static buffers. */
const char *kh_path(const char *name);
/* Removes the directory made by kh_tmpdir and the files in it. */
void kh_rm_tmpdir(void);

/* Writes text to path (atomically: a temporary file renamed over it, as an
 * editor would, so the kiosk never reads half a file).  Exits on failure. */
void kh_write(const char *path, const char *text);
/* The whole file, NUL-terminated, malloc'ed; NULL if unreadable. */
char *kh_read(const char *path);
/* Lines in path that start with prefix. */
int kh_count_lines(const char *path, const char *prefix);

/* Starts argv[0] with stdout and stderr appended to err_path.  Returns the
 * pid, or -1. */
pid_t kh_spawn(char *const argv[], const char *err_path);
/* Waits up to timeout_s for pid; returns its wait status, or -1 on
 * timeout (the process is then killed). */
int kh_wait(pid_t pid, double timeout_s);
/* Waits up to timeout_s until path has at least n lines starting with
 * prefix; 1 if so, 0 on timeout or if pid died first. */
int kh_wait_lines(pid_t pid, const char *path, const char *prefix, int n, double timeout_s);
void kh_sleep(double s);

/* The kiosk's picture at a fixed exposure: the kiosks these tests run are
 * given --exposure 0 (x 1; the automatic exposure smooths over wall-clock
 * time, so its frames are not reproducible byte for byte) and show the
 * hue-keeping curve (hfs_io.h HFS_TONEMAP_HUE). */
#define KH_PICTURE ((hfs_png_opts){.exposure = 1.0, .tonemap = HFS_TONEMAP_HUE})

/* Reads an RGBA8 PNG; malloc'ed pixels or NULL. */
uint8_t *kh_png_rgba(const char *path, int *w, int *h);

/* Renders scene_path (with key light 0 replaced by phi/elev when
 * key_phi is not NAN) with a fresh GLES renderer, made into the kiosk's
 * picture (frame_image.h, KH_PICTURE).  Returns the malloc'ed RGBA8
 * picture or NULL with the reason printed.  *no_gl is set when no GL
 * context could be made. */
uint8_t *kh_direct_frame(const char *scene_path, double key_phi, double key_elev, int *w,
                         int *h, int *no_gl);
/* As kh_direct_frame, the scene's 3-D view as the kiosk's camera makes it
 * (board/KIOSK.md "3-D view": perspective, 40 degrees high, from azimuth
 * and elevation az, el in degrees, at zoom times the distance that frames
 * the field, against the sky through the automatic haze), vw x vh pixels. */
uint8_t *kh_direct_view(const char *scene_path, double az, double el, double zoom, int vw,
                        int vh, int *no_gl);

/* Returns when a GLES renderer can be made here; otherwise exits 77 when no
 * GLES context of any kind can be made, 1 when the renderer is broken
 * (gl_test.h). */
void kh_require_gl(void);

#endif /* HFS_KIOSK_HARNESS_H */
