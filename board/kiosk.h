/*
 * kiosk.h — the kiosk program's parts (private to hfshade-kiosk).
 *
 *   kiosk_main.c   command line, start-up order, teardown, exit codes
 *   kiosk_world.c  scene file + input configuration + knob state: loaded
 *                  together, checked together, replaced whole on SIGHUP
 *   kiosk_frame.c  render -> sRGB picture -> overlay -> present (or, on a GL
 *                  display, the renderer's texture -> present: no read-back)
 *   kiosk_loop.c   the poll loop: signals, display, devices, replay
 *   kiosk_stats.c  the --stats file (latency and CPU measurements)
 *   kiosk_log.c    one line per event of note, journal priorities
 *
 * board/KIOSK.md is the user's documentation.  One kiosk per process (the
 * logger's journal flag is per process); everything else lives in the
 * kiosk struct, freed by kiosk_main.c.
 */
#ifndef HFS_KIOSK_H
#define HFS_KIOSK_H

#include <poll.h>
#include <stdint.h>
#include <stdio.h>
#include <sys/types.h>

#include "capture_live.h"
#include "display.h"
#include "input_map.h"
#include "input_set.h"
#include "kiosk_map.h"
#include "scene_load.h"

/* ---- logging (kiosk_log.c) ------------------------------------------------ */

/* sd-daemon priorities (sd-daemon.h: SD_ERR "<3>", SD_WARNING "<4>",
 * SD_INFO "<6>"), prefixed when stderr is the journal. */
typedef enum kiosk_level {
    KIOSK_ERR = 3,
    KIOSK_WARNING = 4,
    KIOSK_INFO = 6
} kiosk_level;

/* Decides once whether stderr is the journal: JOURNAL_STREAM ("DEV:INODE",
 * set by systemd) names the device and inode of stderr itself (a child
 * whose stderr was redirected inherits the variable but not the stream). */
void kiosk_log_init(void);
/* One line on stderr: "<N>message" to the journal, "hfshade-kiosk: message"
 * elsewhere.  Newlines in the message are replaced, so one call is always
 * one line. */
void kiosk_log(kiosk_level level, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* ---- options (kiosk_main.c) ------------------------------------------------ */

typedef struct kiosk_opts {
    const char *scene_path;        /* required                                */
    const char *input_path;        /* --input; NULL = no controls            */
    const char *replay_path;       /* --replay                               */
    const char *display;           /* --display; default "kms"               */
    const char *out_pattern;       /* --out (headless)                       */
    const char *stats_path;        /* --stats                                */
    int width, height;             /* --size (x11 window, headless canvas)   */
    double exposure;               /* --exposure EV as a multiplier 2^EV;
                                      0 = auto, the default                  */
    int overlay;                   /* --overlay: start with the overlay on   */
    int view;                      /* --view: start in the 3-D view          */
    int exit_after_replay;         /* --exit-after-replay                    */
    int no_devices;                /* --no-devices: configured devices are
                                      not opened (replay or demo only)       */
    int check;                     /* --check: load and check, then exit     */
    const char *capture_record;    /* --capture-record DIR                   */
    int exit_after_capture;        /* --exit-after-capture: exit 0 once the
                                      capture replay's last frame is shown   */
    int readback;                  /* --readback: no shared context, the
                                      frame read back and uploaded           */
    int amortize;                  /* --amortize N: visibility passes per
                                      frame (hfs_renderer_set_amortize); 0 =
                                      off, the default                       */
} kiosk_opts;

/* ---- the world: scene + configuration + knob state (kiosk_world.c) -------- */

typedef struct kiosk_world {
    hfs_scene scene;               /* as loaded, then edited by the knobs    */
    hfs_scene_inputs in;           /* heights, env SH, lighting, quality     */
    hfs_input_config cfg;          /* zero controls without --input          */
    hfs_input_state st;
} kiosk_world;

/* Loads the scene file and the configuration (NULL: none), checks the
 * configuration against the scene (fixed light indices) and initialises the
 * knob state.  Returns a new world, or NULL with err set (one line naming
 * the file).  The caller frees it with kiosk_world_free. */
kiosk_world *kiosk_world_load(const char *scene_path, const char *input_path, hfs_error *err);
void kiosk_world_free(kiosk_world *w);   /* NULL ok */

/* After knob edits to w->scene: recomputes lighting and quality (no file is
 * read).  On failure the previous lighting stays. */
int kiosk_world_relight(kiosk_world *w, hfs_error *err);

/* ---- frames (kiosk_frame.c) ----------------------------------------------- */

typedef struct kiosk_frame {
    hfs_renderer *renderer;
    hfs_backend backend;           /* what the renderer was made with, to    */
    char context[64];              /* know when a reload needs a new one     */
    hfs_image img;                 /* linear RGB, reused                     */
    hfs_image small;               /* img shrunk to the display's largest
                                      side (shrink > 1), reused              */
    int shrink;                    /* picture = img / shrink per side        */
    uint8_t *rgba;                 /* sRGB picture, reused                   */
    double exposure;               /* the multiplier the picture is shown at */
    /* Automatic exposure (auto = 1: no --exposure EV): each frame metered
     * on its lit grid (hfs_exposure_auto: terrain only, also in the 3-D
     * view), the shown exposure smoothed towards it over time
     * (hfs_exposure_smooth, HFS_KIOSK_EXPOSURE_TAU).  The texture path has
     * no image on the CPU: it meters by a read-back at most every
     * KIOSK_METER_NS and smooths towards the last target in between. */
    int auto_exposure;
    double ev, target_ev;          /* stops; ev NAN until the first meter    */
    int64_t ev_ns, metered_ns;     /* when ev was last stepped, metered      */
    int settling;                  /* ev not yet at the target: the loop
                                      shows another frame soon               */
    hfs_image lit;                 /* the lit grid metered in the 3-D view and
                                      on the texture path, reused            */
    int presented;                 /* frames presented so far                */
    int amortize;                  /* applied to every renderer made         */
    int deferred;                  /* passes the last frame left for later:
                                      the loop renders again at once         */
    /* Last frame, for the overlay and the stats. */
    double render_ms;
    int passes_ran, passes_total;
    int view_w, view_h;            /* the 3-D view's size: --size, or 800x480 */
    /* Embedding (issue 20): the GL display's EGL display and context
     * (NULL: headless, or --readback); a GLES renderer made with them
     * shares the display's context (shared = 1) and a grid frame goes to
     * the screen as its texture, with no read-back and no upload. */
    void *egl_display, *egl_context;
    int shared;
    int64_t present_ns;            /* CLOCK_MONOTONIC after present returned */
    /* The map (kiosk_map.h): a field larger than the display, shown at
     * the display's size (--size, or a KMS mode's), panned and zoomed
     * (map.* actions).  NULL: the field shown whole (shrunk to fit). */
    kiosk_map *map;
    int map_w, map_h;              /* the display size maps are made for (0:
                                      none): --size, or the KMS mode's       */
    int prefetching;               /* the map's last view still wants tiles:
                                      the loop fetches one when idle         */
} kiosk_frame;

/* Makes the renderer the scene asks for (backend, context), exposure the
 * picture's multiplier (0: automatic): a GLES one in
 * the share group of display d's GL context when d has one (NULL: none,
 * every frame read back). */
int kiosk_frame_init(kiosk_frame *f, const hfs_scene *scene, double exposure, hfs_display *d,
                     hfs_error *err);
/* For a reload, in two steps so that nothing changes until every part of
 * the reload has worked: *out = a new renderer when scene asks for another
 * backend or context than f's, else NULL (f's fits).  Then adopt (r NULL:
 * keep f's), or hfs_renderer_destroy(r) to abandon. */
int kiosk_frame_renderer_for(const kiosk_frame *f, const hfs_scene *scene, hfs_renderer **out,
                             hfs_error *err);
void kiosk_frame_adopt(kiosk_frame *f, hfs_renderer *r, const hfs_scene *scene);
/* The admission check of a scene: one whole frame of it (no amortizing)
 * rendered with r into a scratch image; the display is not touched.  r NULL:
 * a renderer made for the scene (--check) and destroyed again.  A scene
 * that passes loads, checks, AND renders here; a failure leaves r usable
 * (invalidated: its next frame redoes every pass).  r's amortization is
 * set back to `amortize` afterwards. */
int kiosk_frame_admit(hfs_renderer *r, int amortize, const hfs_scene *scene,
                      const hfs_scene_inputs *in, hfs_error *err);
void kiosk_frame_free(kiosk_frame *f);

/* The map of in's field for a display of dw x dh pixels (kiosk_map.h),
 * when the field is larger (0 x 0 or a field that fits: none), and st's
 * map state for it: a new field (keep 0) is shown whole, centred; keep 1
 * keeps st's place and level where they still lie on the field. */
int kiosk_frame_map(kiosk_frame *f, const hfs_scene_inputs *in, hfs_input_state *st, int dw,
                    int dh, int keep, hfs_error *err);
/* Renders one tile the map's view wants (kiosk_map_prefetch); clears
 * f->prefetching when none is left.  As kiosk_map_prefetch: 2 one of the
 * view's own (shown from a coarser level until now: show the view again),
 * 1 one ahead of it, 0 none; or an error. */
int kiosk_frame_prefetch(kiosk_frame *f, const hfs_scene_inputs *in, hfs_error *err);

/* Renders in (its grid dump, or with st->view the 3-D view from st's
 * camera: view_camera), makes the picture, draws the overlay when st asks,
 * presents it and fills the "last frame" fields. */
int kiosk_frame_show(kiosk_frame *f, const hfs_scene_inputs *in, const hfs_input_state *st,
                     const char *preset, hfs_display *d, hfs_error *err);
/* The 3-D view st's camera shows of field (perspective, 40 degrees high,
 * framing the field times st->cam_zoom), w x h pixels; behind and over it
 * what hfshade render's view shows by default (tools/cli_view.h): a
 * terrain against its sky through the automatic haze, a panel (panel
 * non-zero: preset = panel) in the studio without haze. */
hfs_view kiosk_view_camera(const hfs_input_state *st, const hfs_field *field, int w, int h,
                           int panel);

/* ---- stats (kiosk_stats.c) -------------------------------------------------- */

typedef struct kiosk_stats kiosk_stats;

/* Opens (truncates) path and writes the header; NULL with err on failure. */
kiosk_stats *kiosk_stats_open(const char *path, hfs_error *err);
/* Lines: see kiosk_stats.c.  Each function is a no-op on NULL. */
void kiosk_stats_start(kiosk_stats *s);
void kiosk_stats_frame(kiosk_stats *s, const kiosk_frame *f, int events);
void kiosk_stats_event(kiosk_stats *s, const hfs_input_event *ev, int changed,
                       const kiosk_frame *f, int shown);
void kiosk_stats_reload(kiosk_stats *s, int ok);
/* "prefetch T_NS LEVEL TILE_MS CACHED BYTES" after the map rendered a tile
 * ahead of its view. */
void kiosk_stats_prefetch(kiosk_stats *s, const kiosk_frame *f);
/* "capture SEQ T_FRAME_NS T_PRESENT_NS LATENCY_NS CPU_NS DROPPED SUPERSEDED" after the
 * frame that showed a capture frame's heights. */
void kiosk_stats_capture(kiosk_stats *s, const hfs_capture_live *live, const kiosk_frame *f);
/* "sky SEQ T_FRAME_NS T_PRESENT_NS LATENCY_NS CPU_NS DROPPED SUPERSEDED NLIGHTS
 * [ID PHI_DEG ELEV_DEG]..." after the frame that showed a sky frame's
 * lighting. */
void kiosk_stats_sky(kiosk_stats *s, const hfs_capture_live *live, const kiosk_frame *f);
void kiosk_stats_flush(kiosk_stats *s);
/* Writes "exit"; -1 if any stats write failed (logged when it did). */
int kiosk_stats_close(kiosk_stats *s, int frames);
/* Process CPU time (user + system, all threads), microseconds. */
int64_t kiosk_cpu_us(void);

/* ---- the loop (kiosk_loop.c) ------------------------------------------------ */

/* ---- a reload's admission, checked in a child process (kiosk_check.c) ----- */

/* SIGHUP starts `hfshade-kiosk SCENE [--input CONFIG] --check` (this very
 * program, /proc/self/exe): it loads both files and renders the new scene's
 * first frame off screen with a renderer of its own, exactly the admission
 * a reload needs, while this process keeps running the old scene, reading
 * its knobs and answering SIGTERM at once (a 4096^2 field's admission frame
 * takes a minute on llvmpipe; a signal waited for all of it).  Its stderr
 * comes back through a pipe: the failure's one line. */
typedef struct kiosk_check {
    pid_t pid;                     /* 0: none running                        */
    int fd;                        /* read end of its stderr; -1             */
    char out[1024];                /* what it wrote (the tail)               */
    size_t len;
    int again;                     /* SIGHUP while it ran: check once more   */
} kiosk_check;

void kiosk_check_init(kiosk_check *c);
/* Starts the check of o's scene and configuration.  Fails (nothing
 * started) when the program cannot be spawned. */
int kiosk_check_start(kiosk_check *c, const kiosk_opts *o, hfs_error *err);
/* After POLLIN (or POLLHUP) on c->fd: reads what is there.  Returns 1 when
 * the check has ended (c is idle again): *ok = it admitted the scene, msg =
 * its last line otherwise; 0 while it runs. */
int kiosk_check_poll(kiosk_check *c, int *ok, char *msg, size_t size);
/* Ends a running check (SIGKILL) and reaps it: 1 when it was still
 * running (it died of that SIGKILL), 0 when none ran or it had ended. */
int kiosk_check_stop(kiosk_check *c);

typedef struct kiosk {
    kiosk_opts opt;
    hfs_capture_live *capture;     /* NULL: no [capture] with role = heights  */
    hfs_capture_live *capture_env; /* NULL: none with role = environment      */
    kiosk_check check;             /* the running reload check, if any       */
    kiosk_world *world;
    kiosk_frame frame;
    hfs_display *display;
    hfs_input_set *inputs;         /* the configured devices                  */
    hfs_input_source *replay;      /* kept apart from the set: a reload
                                      rebuilds the set, the script goes on    */
    kiosk_stats *stats;
    int sigfd;                     /* signalfd for SIGHUP, SIGTERM, SIGINT    */
} kiosk;

/* The input set for cfg: every configured device, or none with
 * --no-devices.  Errors name the device. */
int kiosk_inputs_create(const kiosk *k, const hfs_input_config *cfg, hfs_input_set **out,
                        hfs_error *err);

/* Opens the configuration's first role = heights capture into k->capture
 * (its grid defaults to w's field size) and its first role = environment
 * capture into k->capture_env (none: nothing to do). */
int kiosk_capture_open(kiosk *k, const kiosk_world *w, hfs_error *err);
/* Takes the newest frame: 1 when the heights changed (w's field now shows
 * them), 0 otherwise.  Losses and bad frames are logged, never fatal. */
int kiosk_capture_drain(hfs_capture_live *live, kiosk_world *w);
/* Points w's field at the capture's heights (after a reload). */
void kiosk_capture_apply(hfs_capture_live *live, kiosk_world *w);
/* The sky camera: its lighting (smoothed SH, lights) into w and w
 * relit; 1 when the lighting changed.  _drain takes the newest frame
 * first; _apply alone after a reload. */
int kiosk_capture_sky_drain(hfs_capture_live *live, kiosk_world *w);
int kiosk_capture_sky_apply(hfs_capture_live *live, kiosk_world *w);

/* Runs until SIGTERM/SIGINT, a close request, the end of the replay
 * (--exit-after-replay) or a fatal error.  Returns 0 (clean) or 1. */
int kiosk_run(kiosk *k);

#endif /* HFS_KIOSK_H */
