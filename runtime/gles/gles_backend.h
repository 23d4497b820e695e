/*
 * gles_backend.h — the GLES backend's private state, shared by its files
 * (not installed, not for the other backends).
 *
 *   gles_backend.c   the object: create/destroy, settings, hfs_gles_render
 *                    (which lights contribute, the frame's light data)
 *   gles_frame.c     one frame: limits, resources, the plan, the loop over
 *                    the pass table
 *   pass_*.c         the passes (pass.h), one file each
 *   pass_common.c    what the passes share (scratch, stage timing, grid
 *                    inputs and draws), below them: never calls a pass
 *   resources.c      textures and framebuffers
 *   programs.c       the program cache (programs.def)
 *   wedge_textures.c the table path's wedge tables as textures
 *   timing.c         per-pass GPU times
 *   plan.c           the frame as a frame_plan.h graph (from the pass table)
 *   layout.c, uniform_blocks.c   the CPU side: sizes, heights, std140 blocks
 */
#ifndef HFS_GLES_BACKEND_H
#define HFS_GLES_BACKEND_H

#include "albedo_texture.h"
#include "env_map_textures.h"
#include "backends.h"
#include "block_texture.h"
#include "bounce_targets.h"
#include "gl_caps.h"
#include "gl_context.h"
#include "edit_frame.h"
#include "gloss.h"
#include "key_setup.h"
#include "lights.h"
#include "pass.h"
#include "plan.h"
#include "programs.h"
#include "resources.h"
#include "split_horizon.h"
#include "timing.h"
#include "uniform_blocks.h"
#include "wedge_textures.h"

/* Uniform buffers (one per block content; the key swaths and records are
 * two buffers, bound by range). */
enum { HFS_UBO_SCALES, HFS_UBO_ENV_SWATH, HFS_UBO_KEY_SWATHS, HFS_UBO_SHADE, HFS_UBO_KEYS,
       HFS_UBO_LOCAL, HFS_UBO_BOUNCE, HFS_UBO_VIEW, HFS_UBO_FAR_SWATH, HFS_UBO_COUNT };

/* One key light of the frame. */
typedef struct hfs_gles_frame_key {
    hfs_gles_key k;
    hfs_visibility *vis;
    size_t swath_off;  /* bytes into HFS_UBO_KEY_SWATHS */
    size_t swath_size; /* bytes */
    int rec_off;       /* vec4 into HfsKeys */
} hfs_gles_frame_key;

/* What one frame is computed from, and what its passes hand each other. */
struct hfs_gles_frame {
    const hfs_field *f;
    const hfs_quality *q;
    hfs_image *out;
    hfs_gles_layout L;
    int tables;                           /* the wedge-table visibility path */
    int slice;                            /* exact slice lighting (slice_light.h) */
    int hor_layers;                       /* slice path: grid horizon layers (4 directions
                                             each, 2 with hor_pairs) */
    int env_near;                         /* slice path: 1, the texel's own cell is per texel */
    int hor_pairs;                        /* slice path, sub-sampled grid: each horizon as
                                             its occluder (height, distance), 2 a texel */
    int hor_outs;                         /* slice path: targets (layers) a grid draw fills */
    /* Split horizons (split_horizon.h, env_far_grid.c): the near pass stops
     * at scale index env_coarsest; the far grid (step split.step, far_w x
     * far_h receivers) holds the sub-directions' occluders, 2 a texel, in
     * an atlas of tiles (far_cols a row, far_aw x far_ah), skipping the
     * far_near near scales. */
    hfs_split split;
    int env_coarsest, far_near, far_w, far_h, far_cols, far_aw, far_ah;
    int far_swath_tex;                    /* the sub-directions' block from a texture */
    int has_env, n_keys;
    hfs_gles_frame_key keys[HFS_MAX_KEY_LIGHTS];
    double l_env[3][HFS_SH_N];            /* rotated environment SH */
    /* env-shade = map (env_map_textures.h): 0 none, 1 the open-sky table
     * (HFS_ENV_MAP 1), 2 that and the map's occluded light along the
     * slices (the slice path with env_shade_map). */
    int env_map;
    /* 1: the SH sky's occluded light is dotted per texel by the sky
     * occlusion pass, no transfer kept (gles_frame.c env_fold). */
    int env_fold;
    /* 1: a glossy frame with env_map > 0 and env_shade_map: the lobe adds
     * the map's beyond order 4 (env_gloss.h; HFS_GLOSS_MAP). */
    int gloss_map;
    double gloss_map_max;                 /* its table's scale (set by its prepare) */
    const hfs_lighting *l;                /* the frame's lighting */
    double rho_pi;
    const float *albedo;                  /* the lighting's albedo map, or NULL */
    unsigned albedo_gen;                  /* g->albedo's contents' generation */
    hfs_gloss gloss;                      /* glossy surfaces: on = HFS_GLOSSY shading */
    int key_layers;                       /* horizon layers the keys use */
    size_t key_swath_bytes;               /* HFS_UBO_KEY_SWATHS size */
    int key_rec_block;                    /* HfsKeys declared size, vec4 */
    int n_local;                          /* contributing local lights */
    hfs_local_light local[HFS_MAX_LOCAL_LIGHTS];
    int local_open[HFS_MAX_LOCAL_LIGHTS]; /* beyond the shadow range: ratio 1 */
    double out_scale;                     /* power of two (pass_shade.c) */
    int bounces;                          /* indirect bounces (pass_bounce.c) */
    int capped;                           /* their bands stop at the grid's horizons */
    int bsub, bw, bh;                     /* their grid: step (a multiple of L.sub), size */
    /* Uniform data too large for the profile's blocks, carried by textures
     * instead (block_texture.h): decided by the passes' layout hooks. */
    int env_swath_tex, key_swath_tex, keys_tex, local_tex;
    const int *run[HFS_PASS_COUNT];       /* the plan: run[p][instance] */
    /* The 3-D view (pass_view.c): NULL cam when the frame has none. */
    const hfs_camera *cam;
    const hfs_object_set *objects;        /* lit, in the view's world, or NULL */
    int view_w, view_h;
    float *view_rgb;                      /* view_w * view_h * 3, row 0 at the top */
    /* Embedding (pass_lit_texture.c): the texture wanted instead of the
     * image (out is then NULL), or NULL. */
    const hfs_lit_texture_desc *lit;
    /* 1: a frame after an edit of the heights: the passes recompute only
     * the regions g->edit gives them (edit_frame.h). */
    int edit;
};

/* The lit texture handed to the application (pass_lit_texture.c), in the
 * share group of its context. */
typedef struct hfs_gles_lit_texture {
    GLuint tex, fbo;
    int w, h;
    GLenum format;                        /* GL_RGBA16F or GL_RGBA8 */
    GLsync fence;                         /* after the last frame's draw */
} hfs_gles_lit_texture;

typedef struct hfs_gles_view_state hfs_gles_view_state; /* pass_view.c */

struct hfs_gles {
    hfs_gl_context *ctx;
    hfs_gl gl;
    hfs_gl_driver driver;
    hfs_gl_caps caps;                     /* this frame's profile */
    char profile[16];                     /* "" = by precision */
    int strict_limits;                    /* ES 3.0 minimums, not the driver's */
    GLuint vao;
    GLuint ubo[HFS_UBO_COUNT];
    hfs_gles_programs programs;
    hfs_gles_resources r;
    hfs_gles_wedge_textures wedge;
    hfs_gles_albedo_texture albedo;       /* the lighting's albedo map, if any */
    hfs_gles_bounce_targets bounce;       /* the bounce pass's textures, once used */
    hfs_gles_env_map_textures envmap;     /* env-shade = map: its tables, once used */
    hfs_gles_block_texture env_swath_tex, key_swath_tex, keys_tex, local_tex, far_swath_tex;

    /* Terrain cache: what the terrain pass computed from. */
    int terrain_valid;
    float *terrain_z;
    size_t terrain_cap;
    int t_w, t_h, t_k, t_offset, t_fp32;
    double t_dx, t_zscale;
    double t_base, t_hscale, t_vmax;      /* its normalization (layout.h) */
    hfs_gles_edit edit;                   /* the last edit's regions (edit_frame.h) */

    hfs_gles_plan plan;
    hfs_gles_plan plan_dry;               /* a copy to ask what a frame would run */
    hfs_field_extent extent;              /* of the kept terrain (lights.h) */
    int extent_valid;
    int key_stride;                       /* horizon layers per key slot */
    float *last_img;                      /* the last image read back, RGB */
    size_t last_img_cap;
    hfs_visibility *env_vis;
    int env_vis_n;
    hfs_slice_table env_slices;           /* --visibility slice: of env_vis's swath */
    int env_slices_n;

    /* Whether the sky has been turned or re-tinted between two frames: from
     * then on the renderer keeps the transfer (a turn costs the shading),
     * before it only the sky occlusion (gles_frame.c env_fold). */
    double env_seen[3][HFS_SH_N];         /* the last frame's sky */
    int env_seen_valid, env_turned;
    int heights_edited;                   /* a frame's heights changed (gles_frame.c grid_release) */
    double lit_scale;                     /* out_scale of the last shaded frame */
    hfs_gles_view_state *view;            /* the 3-D view's targets (pass_view.c) */
    int shared;                           /* ctx shares the application's objects */
    hfs_gles_lit_texture lit;             /* pass_lit_texture.c */

    hfs_gles_timing timing;
    int stage_slot[HFS_PASS_COUNT];       /* first timing slot of each pass */
    hfs_timings last;
    hfs_gles_stats stats;
    char *scratch;
    size_t scratch_cap;
};

/* The frame's lit result as textures (hi, lo; RGB times fr->out_scale):
 * the shading pass's output, or direct + indirect when the frame has
 * bounces.  What the read-back and any later pass read. */
void hfs_gles_lit_targets(const hfs_gles *g, const hfs_gles_frame *fr, GLuint tex[2]);
/* The view's kept image (1) copied into fr->view_rgb, or 0 when there is
 * none of that size; and the view's GL objects freed (pass_view.c). */
int hfs_gles_view_copy_kept(const hfs_gles *g, hfs_gles_frame *fr);
void hfs_gles_view_free(hfs_gles *g);

/* Embedding (pass_lit_texture.c): the texture black (a frame no light
 * reaches), the frame's fence made and flushed and *out filled; and the
 * texture and fence freed. */
int hfs_gles_lit_texture_black(hfs_gles *g, int w, int h, const hfs_lit_texture_desc *how,
                               hfs_error *err);
int hfs_gles_lit_texture_hand_out(hfs_gles *g, hfs_lit_texture *out, hfs_error *err);
void hfs_gles_lit_texture_free(hfs_gles *g);

/* Scratch memory of at least `bytes`, kept between frames (NULL: none;
 * pass_common.c, as are the stage timing and grid helpers below). */
void *hfs_gles_scratch(hfs_gles *g, size_t bytes);
/* One frame (gles_frame.c): fr holds the frame's lights. */
int hfs_gles_frame_render(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err);

/* Timing of stage `stage` of pass `p` (pass.h stages). */
void hfs_gles_stage_begin(hfs_gles *g, hfs_gles_pass_id p, int stage);
void hfs_gles_stage_end(hfs_gles *g, hfs_gles_pass_id p, int stage);
void hfs_gles_stage_fetches(hfs_gles *g, hfs_gles_pass_id p, int stage, double fetches);

/* Why the terrain pass must run again, or NULL when what it computed still
 * holds (the heights are compared with the kept copy; pass_terrain.c).
 * hfs_gles_heights_changed when only the heights did. */
const char *hfs_gles_terrain_change(const hfs_gles *g, const hfs_field *f, const hfs_quality *q);
extern const char hfs_gles_heights_changed[];

/* Local edits (edit_frame.c, edit_frame.h; issue 38).
 * begin: the box of this frame's changed heights (g->edit.box) and the
 *   planner's reason; NULL when the edit cannot take the path (the
 *   normalization moved, the change covers most of the field).
 * regions: g->edit's regions for that box, once the frame takes the path
 *   (0; -1 out of memory: the frame is cold).
 * draw: the bound program over region (texels; NULL: all) of a w x h target
 *   whose pixel a is the receiver at texel a step, scissored.
 * far_before / far_after: the far atlas read before and after its pass, and
 *   the receivers that changed marked (g->edit.far).
 * far_uniforms: the far pass's test (u_edit...: env_horizons.frag
 *   far_edit_changes) set on prog; u_edit 0 when the frame is not an edit.
 * transfer: the slices' region (made once a frame, added to the shading's).
 * key: key light q's factor test (u_edit...) set on prog and its draw's
 *   region, added to the shading's; NULL: the whole light. */
const char *hfs_gles_edit_begin(hfs_gles *g, const hfs_gles_frame *fr);
int hfs_gles_edit_regions(hfs_gles *g, const hfs_gles_frame *fr);
void hfs_gles_edit_draw(hfs_gles *g, GLuint fbo, int w, int h, int step, const hfs_tiles *region);
int hfs_gles_edit_far_before(hfs_gles *g, const hfs_gles_frame *fr, hfs_error *err);
int hfs_gles_edit_far_after(hfs_gles *g, const hfs_gles_frame *fr, hfs_error *err);
void hfs_gles_edit_far_uniforms(hfs_gles *g, const hfs_gles_frame *fr,
                                const hfs_gles_program *prog);
const hfs_tiles *hfs_gles_edit_transfer(hfs_gles *g, const hfs_gles_frame *fr);
/* levels: the reconstructed levels' region (the box grown by the coarsest
 * level's reach).  local: the local lights' ratios' region (made once a
 * frame: a receiver reads heights no farther than its distance to a
 * light's centre), added to the shading's grown by the grid's step. */
const hfs_tiles *hfs_gles_edit_local(hfs_gles *g, const hfs_gles_frame *fr);
const hfs_tiles *hfs_gles_edit_levels(hfs_gles *g, const hfs_gles_frame *fr);
const hfs_tiles *hfs_gles_edit_key(hfs_gles *g, const hfs_gles_frame *fr,
                                   const hfs_gles_program *prog, int q, const hfs_key_near *nr);

/* Split horizons' far grid (env_far_grid.c): its sizes and limits (the
 * env pass's layout), its directions' block (prepare), its draw (the env
 * pass's "far" stage; fetch_sum not NULL: its counting twin, the fetches
 * added there), and its texture for the slice passes. */
int hfs_gles_env_far_layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err);
int hfs_gles_env_far_prepare(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err);
int hfs_gles_env_far_draw(hfs_gles *g, const hfs_gles_frame *fr, double *fetch_sum,
                          hfs_error *err);
int hfs_gles_bind_env_far(hfs_gles *g, const hfs_gles_frame *fr, const hfs_gles_program *prog,
                          hfs_error *err);

/* The environment's swath (HfsSwath, or its block texture) for prog
 * (pass_env_horizons.c uploads it). */
int hfs_gles_bind_env_swath(hfs_gles *g, const hfs_gles_frame *fr, const hfs_gles_program *prog,
                            hfs_error *err);
/* The context made current and the profile a frame at q's precision would
 * use (g->caps: its limits). */
int hfs_gles_select_caps(hfs_gles *g, const hfs_quality *q, hfs_error *err);
/* A call outside the frame (point queries, horizons): the context made
 * current, the profile a frame at q's precision would use, the layout (its
 * normalization), and the field checked against the texture limit (one
 * line naming `what`). */
int hfs_gles_begin_outside(hfs_gles *g, const hfs_field *f, const hfs_quality *q,
                           hfs_gles_layout *L, const char *what, hfs_error *err);
/* Binds what hfs_normal_at reads (gles_lib.frag): the heights (u_height:
 * the level array, its layer u_hlayer the last) and their slope factor
 * u_zf. */
int hfs_gles_bind_normals(hfs_gles *g, const hfs_gles_program *prog, const hfs_gles_layout *L,
                          hfs_error *err);
/* Binds the textures every grid pass reads (levels, the heights for the
 * normals) and the per-scale constants, and sets the grid uniforms. */
int hfs_gles_bind_grid_inputs(hfs_gles *g, const hfs_gles_program *prog,
                              const hfs_gles_layout *L, hfs_error *err);
/* Binds the gap search's heights and bounds textures (u_height: layer
 * `layer` of the array texture `heights`; u_bounds: bounds_texture.h) and
 * sets the layer u_hlayer, its atlas offsets u_rb_at and slope factor u_zf:
 * for a program outside the frame (horizons.c) as for the frame's. */
int hfs_gles_bind_ray(const hfs_gl *gl, const hfs_gles_program *prog, const hfs_gles_layout *L,
                      GLuint heights, int layer, GLuint bounds, hfs_error *err);
/* The same with the frame's heights and bounds (g->r), and the search's
 * start u_gap_from (texels). */
int hfs_gles_bind_bounds(hfs_gles *g, const hfs_gles_program *prog, const hfs_gles_layout *L,
                         float gap_from, hfs_error *err);
/* What env_slices.frag writes. */
typedef enum hfs_gles_slices_out {
    HFS_SLICES_TRANSFER, /* T_occ, 16 coefficients in 4 targets (pass_env_transfer.c) */
    HFS_SLICES_MAP,      /* the map's occluded irradiance (pass_env_map_slices.c) */
    HFS_SLICES_SKY       /* T_occ dotted with the SH sky (pass_env_sky_occlusion.c) */
} hfs_gles_slices_out;
/* env_slices.frag over the field into fbo. */
int hfs_gles_draw_env_slices(hfs_gles *g, hfs_gles_frame *fr, hfs_gles_slices_out what,
                             GLuint fbo, hfs_error *err);
/* The slice path's fetches a texel (the normal, the grid's horizons, the
 * near scale's neighbourhood, the far grid), before what `what` adds. */
double hfs_gles_env_slices_fetches(const hfs_gles *g, const hfs_gles_frame *fr);
/* Draws the bound program over the grid into `outs` layers of array
 * texture tex from layer0 (through fbo), over region only (texels; NULL:
 * the grid); with fetch_sum, adds the counts the HFS_COUNT twin wrote to
 * target 0. */
int hfs_gles_draw_grid_layers(hfs_gles *g, const hfs_gles_layout *L, GLuint fbo, GLuint tex,
                              int layer0, int outs, const char *what, const hfs_tiles *region,
                              double *fetch_sum, hfs_error *err);
/* Adds the fetch counts a counting twin wrote to target 0 of fbo (vw x vh;
 * _rect: w x h). */
int hfs_gles_sum_counts(hfs_gles *g, const hfs_gles_layout *L, GLuint fbo, double *sum,
                        hfs_error *err);
int hfs_gles_sum_counts_rect(hfs_gles *g, GLuint fbo, int w, int h, double *sum, hfs_error *err);

/* A key light's near search on layout L's grid (key_setup.h
 * hfs_key_near_make, the CPU reference's too). */
hfs_key_near hfs_gles_key_near_make(const hfs_gles_layout *L, const hfs_swath *s);

/* A key light's irradiance at normal incidence, pi sin^2 alpha: the
 * largest value of its factor (never 0 in float). */
double hfs_gles_key_emax(const hfs_gles_key *k);

#endif /* HFS_GLES_BACKEND_H */
