/*
 * hfshade.h — public interface of libhfshade.
 *
 * hfshade computes the exit radiance of a Lambertian height field lit by an
 * SH environment, distant disk ("key") lights and local spherical lights, with
 * soft shadows, exactly as ../shared/SPEC.md defines it.  Three backends
 * compute the same quantity:
 *   HFS_BACKEND_GLES  the product: OpenGL ES 3.0 + fp16 textures (issue 3);
 *   HFS_BACKEND_CPU   the reference: the same algorithm in double precision;
 *   HFS_BACKEND_TRUTH brute force (exact horizons, ray casting), the oracle.
 *
 * Conventions (SPEC.md is the authority):
 *   - heights H[j][i], i = column (x), j = row (y); world z = zscale * H.
 *   - directions: azimuth phi from +x toward +y, elevation from the plane.
 *   - angles in this API are RADIANS (the command line speaks degrees).
 *   - output: linear RGB exit radiance Lo per grid point, row j = 0 first.
 *
 * Ownership: every *_create returns an object the caller frees with the
 * matching *_destroy; destroy(NULL) is a no-op.  Inputs passed by pointer are
 * only read during the call and never retained.
 *
 * Errors: functions return 0 (HFS_OK) or a negative hfs_status and, when the
 * caller passes an hfs_error, fill it with a one-line message.  The library
 * never prints.  No NaN or Inf is ever written to an output.
 *
 * Threads: objects are not internally locked; use one object per thread.
 * There is no global mutable state, so independent objects may be used from
 * different threads at once.
 *
 * The inputs every render call reads (hfs_field, hfs_lighting, hfs_quality)
 * are declared in hfshade_inputs.h, which this header includes: include
 * only <hfshade.h>.
 */
#ifndef HFSHADE_H
#define HFSHADE_H

#include <stddef.h>
#include <stdint.h>

#include "hfshade_version.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(HFS_BUILDING_LIBRARY) && defined(__GNUC__)
#define HFS_API __attribute__((visibility("default")))
#else
#define HFS_API
#endif

/* ---- status and errors ------------------------------------------------ */

typedef enum hfs_status {
    HFS_OK = 0,
    HFS_E_INVALID = -1,     /* an argument or scene value is out of range  */
    HFS_E_NOMEM = -2,       /* allocation failed                           */
    HFS_E_IO = -3,          /* a file could not be read or written         */
    HFS_E_FORMAT = -4,      /* a file is malformed, truncated or absurd    */
    HFS_E_UNSUPPORTED = -5, /* valid, but this backend/driver cannot do it */
    HFS_E_CONTEXT = -6,     /* no GL context could be made                 */
    HFS_E_GL = -7           /* the GL driver reported an error             */
} hfs_status;

/* A one-line, user-facing message ("FILE: problem").  Always NUL-terminated. */
typedef struct hfs_error {
    char msg[512];
} hfs_error;

/* Formats into err (if non-NULL) and returns code, so callers can write
 * `return hfs_fail(err, HFS_E_FORMAT, "%s: short data", path);`. */
HFS_API int hfs_fail(hfs_error *err, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Stable name of a status code ("invalid", "format", ...). */
HFS_API const char *hfs_status_name(int code);

/* ---- version ------------------------------------------------------------- */

/* The library's version at run time, "MAJOR.MINOR.PATCH", and as
 * MAJOR * 10000 + MINOR * 100 + PATCH; compare with HFS_VERSION_STRING and
 * HFS_VERSION_NUMBER (hfshade_version.h), the headers compiled against. */
HFS_API const char *hfs_version(void);
HFS_API int hfs_version_number(void);

/* ---- the inputs: height field, lights, quality settings -------------------- */

/* hfs_field, hfs_lighting (environment, key and local lights, albedo,
 * bounces, gloss) and hfs_quality with their defaults and presets: what
 * every render call reads, in a header of their own. */
#include "hfshade_inputs.h"

/* Progress callback for long renders (cpu, truth): fraction in [0, 1].
 * Called from the rendering thread only; may be NULL. */
typedef void (*hfs_progress_fn)(void *user, double fraction);

/* ---- output -------------------------------------------------------------- */

/* Linear RGB exit radiance, width*height*3 floats, row j = 0 first. */
typedef struct hfs_image {
    int width, height;
    float *rgb;
} hfs_image;

HFS_API int hfs_image_alloc(hfs_image *img, int width, int height, hfs_error *err);
HFS_API void hfs_image_free(hfs_image *img);

/* ---- the renderer ------------------------------------------------------------ */

/* An opaque renderer bound to one backend.  For the GLES backend it owns the
 * GL context and every GPU resource; the CPU and truth backends own scratch
 * memory only.  Create once, render many frames. */
typedef struct hfs_renderer hfs_renderer;

typedef struct hfs_renderer_desc {
    hfs_backend backend;     /* HFS_BACKEND_DEFAULT: see hfs_backend         */
    const char *context;     /* GLES only: "surfaceless" (default), "osmesa",
                                "auto"; NULL = default                        */
    const char *gl_profile;  /* GLES only: target profile the renderer keeps
                                to whatever the driver offers: "es30-half"
                                (the product), "es30-float", "es32"; NULL =
                                by precision (fp16: es30-half, fp32:
                                es30-float).  See runtime/gl_caps.h.          */
    int gl_strict_limits;    /* GLES only: 0 (default) = every limit
                                (texture size, uniform block size, ...) is
                                the driver's own, so a board that holds a
                                4096^2 field renders it; 1 = capped at the
                                ES 3.0 minimums under the es30 profiles
                                (2048 texels, 16 KiB blocks): how CI checks
                                that a scene runs on ANY ES 3.0 device.  The
                                environment variable HFS_GL_STRICT_LIMITS=1
                                turns it on for every renderer.              */
    /* GLES only, embedding (hfs_renderer_render_texture): the application's
     * EGLDisplay and EGLContext, as void * (this header includes no EGL
     * header); both NULL (default) = the renderer's own headless context
     * (`context`).  Set, the renderer makes its OpenGL ES 3 context on that
     * display in the share group of that context (EGL_NO_SURFACE: the
     * display needs EGL_KHR_surfaceless_context), so the textures it
     * renders are textures of the application's context.  The capability
     * layer still keeps the renderer to gl_profile.  Every renderer call
     * binds the renderer's context and, before returning, binds again
     * whatever context and surfaces were current on the calling thread.
     * The application keeps its context alive until hfs_renderer_destroy. */
    void *egl_display;
    void *egl_share_context;
} hfs_renderer_desc;

HFS_API int hfs_renderer_create(const hfs_renderer_desc *desc, hfs_renderer **out,
                                hfs_error *err);
HFS_API void hfs_renderer_destroy(hfs_renderer *r);

/* The backend actually used ("cpu", "truth", "gles") and, for GLES, the
 * context ("surfaceless", "osmesa"). */
HFS_API const char *hfs_renderer_backend_name(const hfs_renderer *r);

/* Renders one frame: out must be allocated to the field's size.  Every input
 * is validated first (one-line error, nothing written on failure): the
 * heights too, which is a pass over the whole field, unless the caller
 * names their changes with hfs_renderer_set_field_serial.
 * Local edits (GLES): when only some heights changed since the last frame
 * (in place or at a new pointer, nothing else changed, the field's lowest
 * and highest heights kept, the change within half the field), the frame
 * recomputes only what the change can reach (its neighbourhood, and the
 * texels whose horizons or shadows it can move) and is equal, bit for bit,
 * to a frame recomputed from scratch; the frame report's terrain step says
 * "heights edited".  Nothing to call for it.
 * A field larger than one GLES frame holds (the profile's texture limit, at
 * most 4096 texels a side) is rendered in tiles whose halo is sized from
 * its relief and lights (DESIGN.md "GIS horizons", "The lit frame in
 * tiles"); a scene no halo serves (a local light, a key light at or below
 * its own radius, relief too steep for the tiles) is refused in one line
 * naming the way out (the cpu backend renders any size). */
HFS_API int hfs_renderer_render(hfs_renderer *r, const hfs_field *field,
                                const hfs_lighting *lighting,
                                const hfs_quality *quality, hfs_image *out,
                                hfs_progress_fn progress, void *user,
                                hfs_error *err);

/* Heights checked once per change.  Checking every height for NaN/Inf is a
 * pass over the whole field; a caller that renders the same heights frame
 * after frame (a kiosk turning lights) can spare it by giving the heights a
 * serial: a number that names their content.  While the serial is not 0,
 * hfs_renderer_render scans the heights only when the field's z pointer,
 * width, height or the serial differ from those of the last heights it
 * found finite; all other inputs are still checked on every call.
 *   - The contract: whoever changes a height, in place or by pointing z at
 *     other heights, sets a new serial before the next render (count up;
 *     never reuse a serial for other heights at the same address).  Heights
 *     changed under an old serial are not re-checked: such a frame renders
 *     what the backend makes of them or fails, but never succeeds with a
 *     non-finite value in its image.
 *   - 0, the default: no serial, every render scans the heights.
 * hfs_renderer_invalidate forgets what was checked.  Kept until changed. */
HFS_API void hfs_renderer_set_field_serial(hfs_renderer *r, uint64_t serial);

/* ---- objects above the field (issue 19) ---------------------------------------- */

/* What stands above the terrain in a 3-D view: markers, pins, boxes
 * (runtime/core/objects.h, DESIGN.md "Objects above the field").  Each is an
 * axis-aligned box lit by the scene's lights: key lights through their
 * visibility at its surface (the renderer's point query: shadow height
 * maps, exact rays on the truth), the environment through horizons
 * marched from its surface's own height, local lights unshadowed.  They
 * cast no shadows (on the terrain or each other). */
#define HFS_MAX_OBJECTS 256
typedef enum hfs_object_kind {
    HFS_OBJECT_POINT = 0,    /* a cube of side size[0] centred z above the surface */
    HFS_OBJECT_PIN,          /* a square post size[0] wide and size[2] high, its
                                foot z above the surface                      */
    HFS_OBJECT_BOX           /* size[0] x size[1] x size[2] along x, y, z, its
                                bottom z above the surface                    */
} hfs_object_kind;

typedef struct hfs_object {
    hfs_object_kind kind;
    double x, y;             /* its centre, world units, on the footprint     */
    double z;                /* above the surface at (x, y) (bilinear), >= 0  */
    double size[3];          /* world units, > 0 where the kind reads them    */
    float albedo[3];         /* linear RGB in [0, 1]                          */
} hfs_object;

/* ---- the 3-D view (issue 16) -------------------------------------------------- */

/* A picture of the lit field seen from a camera, instead of its grid dump
 * (docs/DESIGN.md "The 3-D view's truth", "GLES path", "Sky and haze in
 * the view"): the field drawn with its exit radiance (diffuse: the same
 * from every direction), its background where a pixel sees no terrain
 * (hfs_background), and optionally an aerial perspective (haze) over the
 * terrain and the objects.  The view image is linear radiance like the
 * grid's: its background pixels hold the radiance of whatever background
 * is drawn (the environment map's own values, the studio grey, the
 * colour), in the same units as the terrain, so one exposure serves both.
 * World coordinates are SPEC's, x = i dx, y = j dx,
 * z = zscale H times the view's exaggeration.  The camera orbits
 * `target`: it stands `distance` away in the direction (azimuth,
 * elevation) seen from the target (SPEC's azimuth, from +x toward +y) and
 * looks at it; screen up is +z, and straight down (elevation 90 degrees)
 * +x is to the right and row j = 0 at the top, as in the dumps. */
typedef enum hfs_view_mode {
    HFS_VIEW_PERSPECTIVE = 0,
    HFS_VIEW_ORTHO           /* parallel rays; the view is 2 distance tan(fov/2)
                                high at every depth (what perspective shows at
                                the target), nothing behind the eye's plane  */
} hfs_view_mode;

/* What a pixel that sees no terrain shows. */
typedef enum hfs_background {
    HFS_BACKGROUND_SKY = 0,  /* the environment as it lights the field: an
                                env_map itself (bilinear between its pixel
                                centres, turned by env_rotate), else the SH
                                sky; black without an environment          */
    HFS_BACKGROUND_STUDIO,   /* a neutral grey gradient, 0.12 x level
                                straight down, 0.26 at the horizon, 0.40 at
                                the zenith, level being the unshadowed
                                radiance of a white level surface at the
                                field's centre under the scene's lights (1
                                without any): darker than the lit subject */
    HFS_BACKGROUND_COLOR     /* background_rgb                             */
} hfs_background;

/* hfs_view.haze: ln 2 across the field's diagonal (half the light of its
 * far corner survives at the lowest height) with an environment to
 * scatter, off without one. */
#define HFS_HAZE_AUTO (-1.0)

typedef struct hfs_view {
    hfs_view_mode mode;
    double azimuth, elevation; /* radians; elevation in [-pi/2, pi/2]        */
    double distance;           /* world units, > 0                           */
    double fov;                /* vertical field of view, radians, (0, pi)    */
    double target[3];          /* world point looked at                      */
    double exaggeration;       /* vertical exaggeration of the terrain, > 0  */
    int width, height;         /* the view image, pixels, 1..8192            */
    const hfs_object *objects; /* drawn lit in the view (NULL: none)        */
    int n_objects;             /* 0..HFS_MAX_OBJECTS                         */
    hfs_background background; /* HFS_BACKGROUND_SKY (default)                */
    double background_rgb[3];  /* HFS_BACKGROUND_COLOR: linear radiance, the
                                  field's units, each finite in [0, 1e30]   */
    /* Aerial perspective: 0 off (default: the view bit for bit as without
     * it); > 0 (up to 50) the optical depth along the field's diagonal at
     * its lowest height; HFS_HAZE_AUTO.  A single-scattering haze in an
     * exponential atmosphere (scale height a quarter of the diagonal, in
     * the view's world), L = L_surface T + L_in (1 - T) with L_in the
     * environment's cosine-weighted mean over the upper hemisphere; the
     * terrain and the objects only, never the background (which is the
     * sky through the whole atmosphere already). */
    double haze;
} hfs_view;

/* A view of field f: straight down (azimuth 90, elevation 90 degrees),
 * ortho, fov 30 degrees, exaggeration 1, 512 x 512 pixels, the target at
 * the field's centre at mid height and the distance that frames the field
 * (hfs_view_frame); the sky behind, no haze. */
HFS_API void hfs_view_defaults(hfs_view *v, const hfs_field *f);
/* Sets v->distance so that the whole field (its box, with the view's
 * exaggeration) is in view around v->target. */
HFS_API void hfs_view_frame(hfs_view *v, const hfs_field *f);

/* Renders the lit field (as hfs_renderer_render, into `lit` when it is not
 * NULL: W x H like the field) and its view into `view` (allocated to
 * v->width x v->height, row 0 at the top).  The GLES backend draws the
 * field as a triangle mesh on the GPU, multisampled where the driver
 * allows it; a camera move then costs the view alone (the lighting is
 * kept: hfs_renderer_frame_report; a glossy surface is lit for the
 * camera instead of lighting->view_dir, the direction towards it in an
 * ortho view, each texel's own vector towards its eye in a perspective
 * one (view_from_eye), so a camera move reshades it too).  The CPU reference and the ground truth cast one exact ray per
 * pixel centre over the bilinear surface of their lit image.  Same error
 * conventions as hfs_renderer_render. */
HFS_API int hfs_renderer_render_view(hfs_renderer *r, const hfs_field *field,
                                     const hfs_lighting *lighting,
                                     const hfs_quality *quality, const hfs_view *view,
                                     hfs_image *lit, hfs_image *out, hfs_error *err);

/* ---- embedding: the lit result as a texture (issue 20) ---------------------- */

/* What the texture holds (docs/DESIGN.md "Embedding without a read-back"):
 *   HFS_LIT_RADIANCE  GL_RGBA16F: RGB = the exit radiance Lo of
 *                     hfs_renderer_render, linear, unscaled, converted
 *                     to fp16 (relative error < 2^-10, one fp16 ulp: GL
 *                     leaves the rounding direction to the driver;
 *                     values beyond +-65504, fp16's largest, clamp to it;
 *                     below 2^-14 fp16 subnormals), A = 1.  For an
 *                     application that lights, tone maps or blends in its
 *                     own shaders.
 *   HFS_LIT_SRGB8     GL_RGBA8 (NOT GL_SRGB8_ALPHA8): the kiosk's picture,
 *                     bytes as hfs_srgb8_encode_rgb (hfs_io.h) writes them
 *                     -- tonemap(exposure Lo), sRGB OETF, times 255
 *                     -- A = 255.  Sampled, it gives the already-encoded
 *                     value: write it to a non-sRGB framebuffer as it is. */
typedef enum hfs_lit_encoding {
    HFS_LIT_RADIANCE = 0,
    HFS_LIT_SRGB8
} hfs_lit_encoding;

/* How to encode (NULL: radiance).  exposure, tonemap: HFS_LIT_SRGB8 only,
 * as hfs_png_opts (exposure 0 = 1, else > 0 and finite; tonemap 0 clamp,
 * 1 Reinhard, 2 the hue-keeping max-RGB curve: hfs_io.h hfs_tonemap's
 * values). */
typedef struct hfs_lit_texture_desc {
    hfs_lit_encoding encoding;
    double exposure;
    int tonemap;
} hfs_lit_texture_desc;

/* The lit result in the application's share group.  The renderer owns the
 * texture and the fence: never delete them.  The texture name stays the
 * same from frame to frame while the field's size and the encoding do not
 * change; it is valid until the next hfs_renderer_render_texture or
 * hfs_renderer_destroy.  Texel (i, j) is grid point (i, j): s = (i + 0.5) /
 * width, t = (j + 0.5) / height, row j = 0 at t near 0.  Filtering
 * GL_LINEAR, wrap GL_CLAMP_TO_EDGE, one mip level (the application may
 * change the sampling parameters; they are set again on reallocation).
 *
 * Synchronisation: `fence` is a GLsync of the share group (glFenceSync
 * after the frame's last draw, then glFlush): before the first draw that
 * samples the texture, the application calls
 *     glWaitSync((GLsync)lit.fence, 0, GL_TIMEOUT_IGNORED);
 * in its own context.  A GPU-side wait: the CPU never blocks, unlike
 * glFinish, which would stall the caller for the whole frame (the point of
 * dropping the read-back).  The renderer deletes the fence at the next call
 * (deleting a sync object someone waits on is deferred by GL).  Before the
 * next hfs_renderer_render_texture the application must have flushed
 * (glFlush, or eglSwapBuffers) the draws that read the texture, since the
 * next frame writes it in place. */
typedef struct hfs_lit_texture {
    unsigned texture;        /* GLuint, GL_TEXTURE_2D                        */
    unsigned internal_format; /* GL_RGBA16F (0x881A) or GL_RGBA8 (0x8058)    */
    int width, height;       /* the field's                                  */
    void *fence;             /* GLsync                                       */
} hfs_lit_texture;

/* Renders one frame as hfs_renderer_render would, but hands the lit result
 * back as a texture (no read-back to the CPU; the frame planner skips every
 * pass whose product is kept, so a frame with nothing changed runs no pass
 * and returns the same texture).  Needs the GLES backend made with
 * desc.egl_share_context (else HFS_E_UNSUPPORTED, one line); same input
 * checks and error conventions as hfs_renderer_render; on failure *out is
 * zeroed. */
HFS_API int hfs_renderer_render_texture(hfs_renderer *r, const hfs_field *field,
                                        const hfs_lighting *lighting,
                                        const hfs_quality *quality,
                                        const hfs_lit_texture_desc *how, hfs_lit_texture *out,
                                        hfs_error *err);

/* ---- horizons: the rasters terrain analysts use (issue 39) ---------------- */

/* hfs_horizon_desc and hfs_renderer_horizons: the horizon angles of every
 * grid point along given azimuths, in a header of their own. */
#include "hfshade_horizons.h"

/* ---- points above the field ------------------------------------------------- */

/* Key-light visibility of n points (issue 19: markers, pins, an
 * application's own objects): xyz[3 i .. 3 i + 2] in world units (x = i
 * dx, y = j dx over the field's footprint, z = zscale h; a point under the
 * surface sees nothing), vis[i * n_key + k] the visible fraction of key
 * light k's disk in [0, 1], for every key light in lighting order (disabled
 * ones too: visibility is geometry).  The CPU reference reads Lee & Kim's
 * shadow height maps (runtime/core/shm.h: layers across the disk), the GLES
 * backend builds the same maps on the GPU (doubling passes in fp16 hi +
 * lo), the truth casts exact rays (truth_light_samples per light).
 * Errors: a non-finite point or one off the footprint (one line naming
 * it). */
HFS_API int hfs_renderer_query_points(hfs_renderer *r, const hfs_field *field,
                                      const hfs_lighting *lighting, const hfs_quality *quality,
                                      const double *xyz, int n, float *vis, hfs_error *err);

/* Shadow height maps per key light: layers at HFS_SHM_LAYERS elevations
 * across its disk, e + alpha (2 m / (HFS_SHM_LAYERS - 1) - 1), m = 0 its
 * lowest edge, HFS_SHM_LAYERS / 2 its centre. */
#define HFS_SHM_LAYERS 5

/* The shadow height map of layer `layer` of key light `key`, for an
 * application's own shader (its objects' key-light shadows): out gets W x
 * H floats, row-major like the heights (row j = 0 first), in world z; a
 * point (x, y, z) in world units sees that elevation of the light iff z >=
 * S read bilinearly at grid position (x / dx, y / dx) (clamped to the
 * grid).  Upload it as an R32F or fp16 (hi, lo) texture as the
 * application's profile allows.  The CPU reference and GLES build it as
 * the point queries do (the same map, GLES = CPU to fp16's hi + lo); the
 * truth has none (HFS_E_UNSUPPORTED: it answers points by exact rays). */
HFS_API int hfs_renderer_shadow_height_map(hfs_renderer *r, const hfs_field *field,
                                           const hfs_lighting *lighting,
                                           const hfs_quality *quality, int key, int layer,
                                           float *out, hfs_error *err);

/* ---- measurement ------------------------------------------------------------ */

#define HFS_MAX_PASSES 20

/* One pass of the last frame.  GLES passes, in order: "upload" (heights to
 * the GPU), "normals", "decimate" (pyramid, fine to coarse), "reconstruct"
 * (B-spline to full resolution), "env" (environment horizons + SH
 * visibility), "key" (key-light horizons), "local" (local-light visibility
 * ratios), "transfer" (the environment's per-texel transfer vectors),
 * "keyfactor" (each key light's per-texel E_cap * visible fraction), "shade"
 * (the sum over lights), "readback", "littexture" (the encoding of
 * hfs_renderer_render_texture, instead of the read-back).  The CPU and
 * truth backends report one pass, "render". */
typedef struct hfs_pass_time {
    char name[16];
    double ms;          /* GPU time of the pass (see hfs_timings.method)       */
    double fetches;     /* texture fetches: counted for env/key/local at timing
                           level 2, otherwise the pass's fixed count
                           (env/key/local: -1)                                */
    int cached;         /* 1: not run, its result from an earlier frame was
                           still valid (same terrain and settings)            */
} hfs_pass_time;

typedef struct hfs_timings {
    int n_passes;
    hfs_pass_time pass[HFS_MAX_PASSES];
    double gpu_ms;            /* sum of the passes                            */
    double frame_ms;          /* wall time of hfs_renderer_render             */
    size_t texture_bytes;     /* GPU texture memory the renderer holds        */
    char method[24];          /* "timer-query" (GL timestamps around each
                                 pass), "finish-clock" (glFinish + monotonic
                                 clock) or "wall" (CPU backends)             */
    char device[160];         /* GL context/renderer, or "cpu"                */
} hfs_timings;

/* level 0: off (default); 1: per-pass times; 2: also count the texture
 * fetches of the horizon passes (re-runs them with counting shaders after
 * the frame: slower, and the next frame recomputes the environment).
 * Timing adds synchronization, so timed frames are a little slower. */
HFS_API int hfs_renderer_set_timing(hfs_renderer *r, int level);
/* How the GLES backend times passes: 0 = timer queries where the context has
 * them, else glFinish + clock (default); 1 = always glFinish + clock.  Use 1
 * on llvmpipe to see where the time goes: its timestamps do not cover work
 * it defers to the next flush (a shading pass's draw runs at the readback).
 * The other backends accept and ignore it.  0, or HFS_E_INVALID. */
HFS_API int hfs_renderer_set_timing_finish(hfs_renderer *r, int finish);
/* Timings of the last frame rendered with timing on (zeroed if none). */
HFS_API int hfs_renderer_timings(const hfs_renderer *r, hfs_timings *out);
/* Forget results cached from earlier frames (GLES: the pyramid and the
 * environment visibility are reused while the terrain and settings do not
 * change) and which heights were found finite; the next frame recomputes
 * and checks everything.  For benchmarks.
 * What a GLES renderer keeps of the environment follows how it is used,
 * and invalidating keeps that choice: while the sky (the SH environment,
 * its rotation and tint) stays the same from frame to frame, each texel's
 * occluded sky light (12 bytes a texel at fp16); from the first frame whose
 * sky differs from the last one's, the sky's transfer (32 bytes a texel),
 * so that every later turn or tint costs the shading alone.  Until the sky
 * or an environment map first turns or the heights first change (and
 * without bounces), it also frees the grid's horizons that product is made
 * from (3.4 MiB at 512²): that first turn reruns the environment pass
 * once, that first change of the heights recomputes the frame whole (later
 * edits cost their own region).  Every choice gives the same image, bit
 * for bit. */
HFS_API void hfs_renderer_invalidate(hfs_renderer *r);

/* What the last frame ran and what it skipped, and why (the GLES renderer's
 * frame planner, issue 6: a pass runs only when something it reads changed
 * or it never ran; "cached: nothing it reads changed", "not needed").  The
 * CPU and truth backends report one step, "render". */
#define HFS_REPORT_STEPS 40
typedef struct hfs_frame_step {
    char pass[24];
    int ran;
    char reason[96];
} hfs_frame_step;

typedef struct hfs_frame_report {
    int n_steps, n_ran;
    int n_deferred;          /* passes left for later frames (amortization):
                                render again while this is not 0            */
    hfs_frame_step step[HFS_REPORT_STEPS];
} hfs_frame_report;

HFS_API int hfs_renderer_frame_report(const hfs_renderer *r, hfs_frame_report *out);

/* Amortization (NS09 section 7), GLES only, off (0) by default: while the
 * heights stay the same, at most `passes_per_frame` visibility passes (the
 * environment's, one key light's, one local light's) run in a frame; the
 * others keep their previous results for that frame and run in the next
 * ones, those waiting longest first.  A frame then costs at most that many
 * visibility passes, and a change reaches the image in full after up to
 * ceil(K / passes_per_frame) frames (K: the visibility passes it made
 * stale); frames rendered with no further edit converge to the unamortized
 * image bit for bit.  hfs_frame_report.n_deferred tells whether passes are
 * still waiting.  A change of heights runs everything at once.  The other
 * backends accept and ignore it.  0, or HFS_E_INVALID for a negative count. */
HFS_API int hfs_renderer_set_amortize(hfs_renderer *r, int passes_per_frame);

/* Validation used by hfs_renderer_render, exposed for tools and tests: all
 * inputs, or one group (the field: size, dx, zscale and every height; the
 * lighting; the quality).  The ranges are the scene keys' (docs/SCENE.md)
 * in library units (radians where the scene says degrees); one-line
 * messages name the input ("key light 2: elevation 1.6 is out of range
 * [-1.5708, 1.5708] (radians)"). */
HFS_API int hfs_validate_inputs(const hfs_field *field, const hfs_lighting *lighting,
                                const hfs_quality *quality, hfs_error *err);
HFS_API int hfs_validate_field(const hfs_field *field, hfs_error *err);
HFS_API int hfs_validate_lighting(const hfs_lighting *lighting, hfs_error *err);
HFS_API int hfs_validate_quality(const hfs_quality *quality, hfs_error *err);

/* Exact unshadowed Lo (V = 1) of the scene, any backend-independent: the
 * normalizer of SPEC's error metrics. */
HFS_API int hfs_render_unshadowed(const hfs_field *field, const hfs_lighting *lighting,
                                  const hfs_quality *quality, hfs_image *out,
                                  hfs_error *err);

/* ---- error metrics (SPEC) ------------------------------------------------------ */

/* Differences between a result and a reference on the same grid, over every
 * texel and channel, divided by norm (the largest unshadowed value). */
typedef struct hfs_metrics {
    double mean_abs, rmse, p99_abs, max_abs;
    long nonfinite;          /* non-finite values in the result (must be 0) */
    double norm;
} hfs_metrics;

HFS_API int hfs_compare_images(const hfs_image *result, const hfs_image *reference,
                               double norm, hfs_metrics *m, hfs_error *err);

/* Largest value of an image (e.g. of the unshadowed render). */
HFS_API double hfs_image_max(const hfs_image *img);

#ifdef __cplusplus
}
#endif
#endif /* HFSHADE_H */
