/*
 * resources.h — the GLES backend's textures and framebuffers: what each
 * pass writes and later passes read, allocated to the frame's sizes and
 * kept while they fit.
 *
 * Terrain-sized resources (pyramid levels, transfer vectors, key
 * factors, output) follow the field size, level layout and precision;
 * grid-sized ones (environment visibility, key horizons, local ratios) also
 * follow the sub-sampling, without touching the terrain's.  Each group
 * carries a generation counter bumped when it is reallocated, so that the
 * planner can be told its contents are gone (hfs_gles_plan_lost).
 *
 * Also here: the few GL helpers every pass uses (texture/framebuffer
 * creation, a fullscreen draw, a uniform-buffer upload).
 */
#ifndef HFS_GLES_RESOURCES_H
#define HFS_GLES_RESOURCES_H

#include "gl_api.h"
#include "gl_caps.h"
#include "layout.h"

#define HFS_GLES_RECON_MRT 4 /* levels per y pass: ES 3.0's minimum draw buffers */

typedef struct hfs_gles_resources {
    int valid;
    int w, h, n_levels, lmin, n_layers, vw, vh, fp32;
    GLuint bounds;                        /* the gap search's max pyramid (bounds_texture.h) */
    GLuint lev[HFS_GLES_MAX_LEVELS], lev_fbo[HFS_GLES_MAX_LEVELS];      /* decimated levels */
    GLuint half[HFS_GLES_MAX_LEVELS], half_fbo[HFS_GLES_MAX_LEVELS];    /* W x lh: x pass */
    GLuint arr, arr_fbo[HFS_GLES_MAX_LEVELS];   /* reconstructed levels, one layer each; the
                                                   last: the heights (hi, lo), uploaded */
    GLuint arr_mrt_fbo[HFS_GLES_MAX_LEVELS];    /* layers 4g..4g+3 as 4 targets */
    GLuint venv[4], venv_fbo;                   /* SH visibility on the grid */
    GLuint hor, hor_fbo;                        /* slice path: horizons, 4 directions a layer */
    int hor_layers;
    GLuint far, far_fbo;                        /* split horizons: far occluders, 2 a layer */
    int far_layers, far_w, far_h;
    GLuint keyhz, keyhz_fbo;                    /* key horizons (hi, lo, D), a direction a layer */
    int keyhz_layers;
    GLuint localv, localv_fbo;                  /* local-light ratios, 2 lights per layer */
    int localv_layers;
    GLuint transfer[4], transfer_fbo;           /* T = H * V_env per texel */
    GLuint skyocc[2], skyocc_fbo;               /* or T_occ . L_env (the sky occlusion):
                                                   RGBA (hi, lo_r), RG (lo_g, lo_b) */
    GLuint kf, kf_fbo;      /* key factors f / E_max (hi, lo), a layer per key light */
    int kf_layers;
    GLuint out[2], out_fbo; /* RGB hi, lo: drawn together */
    GLuint out_lo_fbo;      /* lo alone as attachment 0, for the readback */
    size_t bytes, hor_bytes, far_bytes, keyhz_bytes, localv_bytes, kf_bytes;
    size_t transfer_bytes, venv_bytes, skyocc_bytes; /* made on demand (0: none) */
    size_t build_bytes;                      /* lev, half: only while the pyramid is built */
    unsigned terrain_gen, grid_gen, keyhz_gen, localv_gen, kf_gen; /* bumped when reallocated */
} hfs_gles_resources;

/* What the layered textures must hold (they only grow). */
typedef struct hfs_gles_layers {
    int hor;    /* environment horizon layers (slice path; 0: none) */
    int far, far_w, far_h; /* split horizons' far grid: layers (0: none), size */
    int key;    /* key horizon layers (0: none; no key light uses the grid) */
    int venv;   /* 1: the grid's V_env targets (Legendre and table paths) */
    int local;  /* local-light ratio layers */
    int n_keys; /* key factor layers */
} hfs_gles_layers;

/* Fits r to layout L and the layer counts n. */
int hfs_gles_resources_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                              const hfs_gles_layout *L, const hfs_gles_layers *n,
                              hfs_error *err);
/* The pyramid build's own targets (decimated levels, the x pass's
 * intermediates): made when the terrain pass starts, deleted when it ends
 * (nothing else reads them; at 512² 1.96 MiB held between terrain changes
 * otherwise, issue 37). */
int hfs_gles_pyramid_build_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                                  const hfs_gles_layout *L, hfs_error *err);
void hfs_gles_pyramid_build_free(hfs_gles_resources *r, const hfs_gl *gl);

/* The transfer targets (T = H * V_env), made the first time a frame needs
 * them (env-shade = map without a glossy lobe or capped bounces never
 * does: 4 full-resolution RGBA targets, 8 MiB at 512², issue 37). */
int hfs_gles_transfer_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                             hfs_error *err);
/* The sky occlusion's targets (pass_env_sky_occlusion.c), made the first
 * time a frame needs them: a full-resolution RGBA and RG target, 3 MiB at
 * 512^2 (fp16). */
int hfs_gles_skyocc_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                           hfs_error *err);
/* Frees the transfer targets (1: there were some) or the sky occlusion's:
 * a frame keeps one of the two (gles_frame.c). */
int hfs_gles_transfer_free(hfs_gles_resources *r, const hfs_gl *gl);
int hfs_gles_skyocc_free(hfs_gles_resources *r, const hfs_gl *gl);
/* The grid's horizons and the far grid (the slice path's environment
 * visibility) deleted while their sizes stay: a frame that reads them
 * again makes them anew (hfs_gles_grid_horizons_remake) and reruns the
 * pass that fills them (gles_frame.c grid_release, grid_restore; 3.4 MiB
 * at 512², issue 37).  _free returns 1 when it deleted something;
 * _freed says whether they are deleted now. */
int hfs_gles_grid_horizons_free(hfs_gles_resources *r, const hfs_gl *gl);
int hfs_gles_grid_horizons_freed(const hfs_gles_resources *r);
void hfs_gles_grid_horizons_remake(hfs_gles_resources *r, const hfs_gl *gl,
                                   const hfs_gl_caps *c);
/* Deletes everything; the generations move on. */
void hfs_gles_resources_free(hfs_gles_resources *r, const hfs_gl *gl);
size_t hfs_gles_resources_bytes(const hfs_gles_resources *r);

/* ---- helpers ---- */
GLuint hfs_gles_tex_new(const hfs_gl *gl, GLenum target, GLenum fmt, int w, int h, int layers,
                        int linear);
void hfs_gles_tex_delete(const hfs_gl *gl, GLuint *t);
/* A framebuffer with n colour attachments: 2D textures (layer NULL or < 0)
 * or layers of array textures. */
int hfs_gles_fbo_new(const hfs_gl *gl, GLuint *fbo, int n, const GLuint *tex, const int *layer,
                     const char *what, hfs_error *err);
/* Targets a grid draw may fill (hfs_gles_fbo_layers). */
#define HFS_GLES_MAX_OUTS 8
/* Attaches `outs` (<= HFS_GLES_MAX_OUTS, and no more than the context's
 * draw buffers) consecutive layers of array texture tex from layer0 to fbo
 * (the rest of the first 4 attachments detached) and checks completeness. */
int hfs_gles_fbo_layers(const hfs_gl *gl, GLuint fbo, GLuint tex, int layer0, int outs,
                        const char *what, hfs_error *err);
/* One fullscreen triangle into fbo over w x h. */
void hfs_gles_draw(const hfs_gl *gl, GLuint fbo, int w, int h);
void hfs_gles_ubo_upload(const hfs_gl *gl, GLuint ubo, const void *data, size_t bytes);

#endif /* HFS_GLES_RESOURCES_H */
